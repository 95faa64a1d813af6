import type { Selection } from '../../core/store/createConfiguratorStore';
import { detailLevel } from './detailLevel';
import { startFixingDrag } from './fixingDrag';
import { startModuleDrag } from './moduleDrag';
import { moduleOnRail } from './moduleMoves';
import type { PendingPress, PlanGesture } from './planGesture';
import type { PlannerGestureHost } from './plannerGestureHost';
import type { ScreenPoint } from './viewTransform';

/** Selects what a drag picked up, unless it already is (a drag of the selection keeps the selection as it is). */
function selectDragged(host: PlannerGestureHost, selection: NonNullable<Selection>): void {
  const state = host.store.getState();
  if (state.selection?.id !== selection.id) state.select(selection);
}

/**
 * A press moved past the drag threshold at `at`: what it becomes follows what it hit and the zoom
 * level, as taps do. At system level a selected system's fixing dot slides along the chain;
 * zoomed in to modules a module slides along its rail; otherwise a system or an object moves
 * (and is selected), and on the floor the plan pans.
 */
export function startDrag(host: PlannerGestureHost, press: PendingPress, at: ScreenPoint): PlanGesture {
  const { hit, down } = press;
  const state = host.store.getState();
  const zoomedIn = detailLevel(host.view.scale) === 'module';
  const on = hit.moduleId && zoomedIn ? moduleOnRail(state.config, state.catalog, hit.moduleId) : null;
  const fixingSystem = hit.fixing !== undefined && !zoomedIn && state.selection?.id === hit.systemId ? state.config.systems.find((s) => s.id === hit.systemId) : undefined;
  if (fixingSystem && hit.fixing !== undefined) return startFixingDrag(host, fixingSystem, hit.fixing, down);
  if (hit.moduleId && on) {
    const drag = startModuleDrag(host, hit.moduleId, on, down);
    selectDragged(host, { kind: 'module', id: hit.moduleId });
    return drag;
  }
  if (hit.systemId) {
    selectDragged(host, { kind: 'system', id: hit.systemId });
    return { mode: 'system', id: hit.systemId, down, startScale: host.view.scale };
  }
  if (hit.objectId) {
    selectDragged(host, { kind: 'object', id: hit.objectId });
    return { mode: 'object', id: hit.objectId, down, startScale: host.view.scale };
  }
  // The pan starts where the press became a drag, so the plan does not jump by the threshold.
  return { mode: 'pan', last: at };
}
