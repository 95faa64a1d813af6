import type { PlannerGestureHost } from './plannerGestureHost';
import { type PressAnchor, pressDelta } from './pressDelta';
import type { ScreenPoint } from './viewTransform';

/** A whole system being dragged (system level). */
export interface SystemDrag extends PressAnchor {
  mode: 'system';
  id: string;
}

/** Previews the system moved to the pointer, marked invalid where dropping it would be refused (the model's isEnabled, live). */
export function previewSystemDrag(host: PlannerGestureHost, g: SystemDrag, at: ScreenPoint): void {
  const delta = pressDelta(g, at);
  const state = host.store.getState();
  const s = state.config.systems.find((x) => x.id === g.id);
  const invalid = !s || state.isEnabled('moveSystem', { systemId: g.id, x: s.x + delta.x, z: s.z + delta.z }) !== true;
  host.setDrag({ systemId: g.id, delta, invalid });
}

/** One undoable moveSystem to where the pointer let go (or the reason it may not go there). */
export function dropSystemDrag(host: PlannerGestureHost, g: SystemDrag, at: ScreenPoint): void {
  host.setDrag(null);
  const delta = pressDelta(g, at);
  const s = host.store.getState().config.systems.find((x) => x.id === g.id);
  if (!s) return;
  // Positions snap to whole centimetres so the move fields show clean numbers.
  const x = Math.round((s.x + delta.x) * 100) / 100;
  const z = Math.round((s.z + delta.z) * 100) / 100;
  host.run('moveSystem', { systemId: g.id, x, z });
}
