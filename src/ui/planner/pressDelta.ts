import type { PlanPoint, ScreenPoint } from './viewTransform';

/** Where a drag of a whole system or object was pressed, and the view's scale then. */
export interface PressAnchor {
  down: ScreenPoint;
  startScale: number;
}

/** The pointer's movement since the press, in metres at the scale the drag started at: the grabbed point stays under it. */
export function pressDelta(g: PressAnchor, at: ScreenPoint): PlanPoint {
  return { x: (at.sx - g.down.sx) / g.startScale, z: (at.sy - g.down.sy) / g.startScale };
}
