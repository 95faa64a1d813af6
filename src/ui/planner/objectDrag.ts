import { clampObjectDelta } from './clampObjectDelta';
import { followableDelta, movedPlacement } from './objectMoves';
import type { PlannerGestureHost } from './plannerGestureHost';
import { type PressAnchor, pressDelta } from './pressDelta';
import type { ScreenPoint } from './viewTransform';

/** Dropped objects land on whole centimetres, so the fields show clean numbers. */
export const DROP_SNAP = 0.01;

/** A furniture object or imported model being dragged (a wall item only along its wall). */
export interface ObjectDrag extends PressAnchor {
  mode: 'object';
  id: string;
}

/** Previews the object moved with the pointer (kept in the room), marked invalid where moveObject would refuse it. */
export function previewObjectDrag(host: PlannerGestureHost, g: ObjectDrag, at: ScreenPoint): void {
  const state = host.store.getState();
  const o = state.config.objects.find((x) => x.id === g.id);
  if (!o) return;
  const delta = clampObjectDelta(state.config, o, followableDelta(o.placement, pressDelta(g, at)), DROP_SNAP);
  const invalid = state.isEnabled('moveObject', { objectId: g.id, placement: movedPlacement(o.placement, delta, DROP_SNAP) }) !== true;
  host.setDrag({ objectId: g.id, delta, invalid });
}

/** One undoable moveObject to where the object was dropped (snapped to the centimetre), or snaps back and says why. */
export function dropObjectDrag(host: PlannerGestureHost, g: ObjectDrag, at: ScreenPoint): void {
  host.setDrag(null);
  const { config } = host.store.getState();
  const o = config.objects.find((x) => x.id === g.id);
  if (!o) return;
  const d = clampObjectDelta(config, o, followableDelta(o.placement, pressDelta(g, at)), DROP_SNAP);
  if (d.x === 0 && d.z === 0) return;
  host.run('moveObject', { objectId: g.id, placement: movedPlacement(o.placement, d, DROP_SNAP) });
}
