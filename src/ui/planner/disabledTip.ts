import type { ActionName } from '../../core/model/actions/actionDefinitions';

/**
 * A disabled control that was pressed tells the planner with this DOM event (bubbling, cancelable,
 * detail `RefusedDetail`): the planner's tip host (guidance.ts) takes it (preventDefault) and shows
 * the reason in a tip at that control (docs/planner.md, "Reasons at the control"); a control nobody
 * takes it from explains itself in the status line. An event rather than a React context: it costs
 * the first screen nothing, and two planners on one page each hear only their own controls.
 */
export const REFUSED_EVENT = 'luxbox-refused';

export interface RefusedDetail {
  reason: string;
  /** The refused model action, when the control runs one: the tip offers its remedy (core remedyFor). */
  action?: { name: ActionName; params: unknown };
}

export interface TipState extends RefusedDetail {
  /** The control that was pressed: the tip is placed at it, inside the element it is rendered in. */
  target: Element;
  /** The configuration it was pressed on: the tip goes when that changes (the control may move or change). */
  config: unknown;
  seq: number;
}
