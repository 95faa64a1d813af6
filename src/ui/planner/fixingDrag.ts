import { attemptAction } from '../../core/model/actions/actionDefinitions';
import { chainCoordinateAt } from '../../core/model/rails/chainCoordinates';
import type { LightSystem } from '../../core/model/configuration/configuration';
import { suspensionCoordinates } from '../../core/model/rails/suspensionPoints';
import type { PlannerGestureHost } from './plannerGestureHost';
import { type ScreenPoint, screenToWorld } from './viewTransform';

/**
 * A fixing point sliding along its system's chain (system level, the system selected): `start`
 * is the chain coordinate it had, `grab` where along the chain it was pressed relative to it,
 * `lastValid` the last position moveFixingPoint accepted and `lastReason` the refusal last shown.
 */
export interface FixingDrag {
  mode: 'fixing';
  systemId: string;
  index: number;
  start: number;
  grab: number;
  lastValid: number;
  lastReason: string | null;
}

function systemById(host: PlannerGestureHost, id: string): LightSystem | null {
  return host.store.getState().config.systems.find((s) => s.id === id) ?? null;
}

/** The chain coordinate of the rail point nearest a screen point (the pointer projected onto the rails). */
function chainCoordinateUnder(host: PlannerGestureHost, system: LightSystem, at: ScreenPoint): number {
  const p = screenToWorld(host.view, at);
  return chainCoordinateAt(system, host.store.getState().catalog, [p.x, p.z]);
}

/** A press on fixing point `index` of `system` (at `down`) became a drag: the point slides along the chain from where it is. */
export function startFixingDrag(host: PlannerGestureHost, system: LightSystem, index: number, down: ScreenPoint): FixingDrag {
  const start = suspensionCoordinates(system, host.store.getState().catalog)[index].s;
  const grab = chainCoordinateUnder(host, system, down) - start;
  return { mode: 'fixing', systemId: system.id, index, start, grab, lastValid: start, lastReason: null };
}

/** The pointer moved to `at`: the point is asked to follow it along the chain (fixingDragAt). */
export function fixingDragToward(host: PlannerGestureHost, g: FixingDrag, at: ScreenPoint): FixingDrag {
  const system = systemById(host, g.systemId);
  return system ? fixingDragAt(host, g, chainCoordinateUnder(host, system, at) - g.grab) : g;
}

/**
 * The dragged fixing point asked to sit at chain coordinate `requested`: previewed there (snapped)
 * when moveFixingPoint accepts it; otherwise it stays at the last accepted position and the
 * reason is shown (once per new reason), as a dragged module does. Returns the drag as it now is.
 */
function fixingDragAt(host: PlannerGestureHost, g: FixingDrag, requested: number): FixingDrag {
  const { config, catalog } = host.store.getState();
  const outcome = attemptAction(config, 'moveFixingPoint', { systemId: g.systemId, index: g.index, s: requested }, catalog);
  if (outcome.ok) {
    const preview = outcome.next.systems.find((x) => x.id === g.systemId);
    if (!preview) return g;
    const s = suspensionCoordinates(preview, catalog)[g.index].s;
    host.setDrag({ fixingIndex: g.index, preview, s, invalid: false });
    return { ...g, lastValid: s, lastReason: null };
  }
  if (outcome.reason !== g.lastReason) host.explainRefusal(outcome);
  const kept = host.drag && 'fixingIndex' in host.drag ? host.drag.preview : systemById(host, g.systemId);
  if (kept) host.setDrag({ fixingIndex: g.index, preview: kept, s: g.lastValid, invalid: true });
  return { ...g, lastReason: outcome.reason };
}

/** One undoable moveFixingPoint to the last accepted position, when it differs from where the point was. */
export function dropFixingDrag(host: PlannerGestureHost, g: FixingDrag): void {
  host.setDrag(null);
  if (Math.abs(g.lastValid - g.start) < 1e-9) return;
  host.run('moveFixingPoint', { systemId: g.systemId, index: g.index, s: g.lastValid });
}
