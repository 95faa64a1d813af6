import { type PlanPoint, type PlanView, type ScreenPoint, panBy, screenToWorld, worldToScreen, zoomAt } from './viewTransform';

/** Two fingers (or a trackpad pinch) on the plan: the view and the world point under their centre when they went down, and their distance then (px). */
export interface PinchGesture {
  mode: 'pinch';
  view: PlanView;
  world: PlanPoint;
  d0: number;
}

/** A pinch starting `distance` px apart about `centre` on `view`. */
export function startPinch(view: PlanView, centre: ScreenPoint, distance: number): PinchGesture {
  return { mode: 'pinch', view, world: screenToWorld(view, centre), d0: Math.max(1, distance) };
}

/**
 * The fingers moved: the zoom is the ratio of their distance to the starting one (so it does
 * not depend on earlier pinches), and the world point that started under them is put back
 * under their centre (two-finger pan).
 */
export function pinchedView(g: PinchGesture, centre: ScreenPoint, distance: number): PlanView {
  const scaled = zoomAt(g.view, centre, Math.max(1, distance) / g.d0);
  const drift = worldToScreen(scaled, g.world);
  return panBy(scaled, centre.sx - drift.sx, centre.sy - drift.sy);
}
