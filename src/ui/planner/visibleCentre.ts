import type { Room } from '../../core/model/configuration/configuration';
import { type PlanPoint, type PlanView, type Viewport, screenToWorld } from './viewTransform';

/** `p` moved onto the room's floor (clamped to its walls). */
export function insideRoom(room: Pick<Room, 'width' | 'depth'>, p: PlanPoint): PlanPoint {
  return { x: Math.min(room.width, Math.max(0, p.x)), z: Math.min(room.depth, Math.max(0, p.z)) };
}

/** The plan point at the middle of the plan, kept inside the room: where a tapped library item goes. */
export function visibleCentre(room: Pick<Room, 'width' | 'depth'>, view: PlanView, viewport: Viewport): PlanPoint {
  return insideRoom(room, screenToWorld(view, { sx: viewport.width / 2, sy: viewport.height / 2 }));
}
