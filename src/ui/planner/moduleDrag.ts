import { attemptAction } from '../../core/model/actions/actionDefinitions';
import type { Configuration } from '../../core/model/configuration/configuration';
import { type ModuleOnRail, alongRail, moduleOnRail } from './moduleMoves';
import type { PlannerGestureHost } from './plannerGestureHost';
import { type ScreenPoint, screenToWorld } from './viewTransform';

/**
 * A module sliding along its rail (zoomed in to modules): `grab` is where along the module it was
 * pressed, `lastValid` the last offset moveModule accepted and `lastReason` the refusal last shown.
 */
export interface ModuleDrag {
  mode: 'module';
  id: string;
  on: ModuleOnRail;
  grab: number;
  lastValid: number;
  lastReason: string | null;
}

/** A press on module `id` (at `down`, the module `on` its rail) became a drag: the module slides along its rail (the pointer projected onto it). */
export function startModuleDrag(host: PlannerGestureHost, id: string, on: ModuleOnRail, down: ScreenPoint): ModuleDrag {
  return { mode: 'module', id, on, grab: alongRail(on, screenToWorld(host.view, down)) - on.offset, lastValid: on.offset, lastReason: null };
}

/** The pointer moved to `at`: the module is asked to follow it along its rail (moduleDragAt). */
export function moduleDragToward(host: PlannerGestureHost, g: ModuleDrag, at: ScreenPoint): ModuleDrag {
  return moduleDragAt(host, g, alongRail(g.on, screenToWorld(host.view, at)) - g.grab);
}

/**
 * The dragged module asked to start at `requested` metres along its rail: previewed there
 * (snapped) when moveModule accepts it; otherwise it stays at the last accepted position and
 * the reason is shown (once per new reason, not on every pointer move). Returns the drag as it
 * now is (the gesture the controller keeps).
 */
function moduleDragAt(host: PlannerGestureHost, g: ModuleDrag, requested: number): ModuleDrag {
  const { config, catalog } = host.store.getState();
  const outcome = attemptAction(config, 'moveModule', { moduleId: g.id, offset: requested }, catalog);
  const systemOf = (c: Configuration) => c.systems.find((x) => x.id === g.on.systemId);
  if (outcome.ok) {
    const on = moduleOnRail(outcome.next, catalog, g.id);
    const preview = systemOf(outcome.next);
    if (!on || !preview) return g;
    host.setDrag({ moduleId: g.id, preview, offset: on.offset, invalid: false });
    return { ...g, lastValid: on.offset, lastReason: null };
  }
  if (outcome.reason !== g.lastReason) host.explainRefusal(outcome);
  const kept = host.drag && 'moduleId' in host.drag ? host.drag.preview : systemOf(config);
  if (kept) host.setDrag({ moduleId: g.id, preview: kept, offset: g.lastValid, invalid: true });
  return { ...g, lastReason: outcome.reason };
}

/** One undoable moveModule to the last accepted position, when it differs from where the module was. */
export function dropModuleDrag(host: PlannerGestureHost, g: ModuleDrag): void {
  host.setDrag(null);
  if (Math.abs(g.lastValid - g.on.offset) < 1e-9) return;
  host.run('moveModule', { moduleId: g.id, offset: g.lastValid });
}
