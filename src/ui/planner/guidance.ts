/**
 * The guidance chunk (issue 27; docs/planner.md "First run", "Reasons at the control"): the empty
 * plan's first step, the tip at a refused control and the remedy it offers. Loaded after the first
 * screen (lazyGuidance.tsx), so the remedy search and these texts cost the first download nothing.
 */

import { createElement, type ComponentProps } from 'react';
import { FirstRunHint, type FirstRunHintProps } from './FirstRunHint';
import { DisabledTip, TipHost } from './DisabledTipView';

export { FirstRunHint, DisabledTip, TipHost };
export { remedyOffer } from './remedyOffer';

/** One lazy component for both parts (lazyGuidance.tsx): the first-run card, or the host of the tips at refused controls. */
export function GuidanceView(props: { firstRun: FirstRunHintProps } | { tips: ComponentProps<typeof TipHost> }) {
  return 'firstRun' in props ? createElement(FirstRunHint, props.firstRun) : createElement(TipHost, props.tips);
}
