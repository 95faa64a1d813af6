import { type PlanView, type ScreenPoint, panBy } from './viewTransform';

/** A press on the floor that became a drag: the plan follows the pointer from where it was `last`. */
export interface PanGesture {
  mode: 'pan';
  last: ScreenPoint;
}

/** `view` moved by the pointer's travel since the pan's last point. */
export function pannedView(view: PlanView, g: PanGesture, at: ScreenPoint): PlanView {
  return panBy(view, at.sx - g.last.sx, at.sy - g.last.sy);
}
