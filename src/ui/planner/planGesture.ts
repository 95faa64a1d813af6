import type { FixingDrag } from './fixingDrag';
import type { ModuleDrag } from './moduleDrag';
import type { ObjectDrag } from './objectDrag';
import type { PanGesture } from './panGesture';
import type { PinchGesture } from './pinchGesture';
import type { PlanHit } from './planHitTest';
import type { SystemDrag } from './systemDrag';
import type { ScreenPoint } from './viewTransform';

/** A press that has not moved past the drag threshold yet: it may still be a tap on what it `hit`. */
export interface PendingPress {
  mode: 'pending';
  down: ScreenPoint;
  hit: PlanHit;
}

/** The gesture under way on the plan, one at a time (docs/planner.md, "Gestures"). */
export type PlanGesture = PendingPress | PanGesture | SystemDrag | ObjectDrag | ModuleDrag | FixingDrag | PinchGesture;
