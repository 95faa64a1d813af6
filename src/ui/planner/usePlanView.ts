import { useLayoutEffect, useState } from 'react';
import type { PlannerController } from './PlannerController';
import { createViewSpring } from './viewSpring';
import type { PlanView } from './viewTransform';

/** Users who ask their system for less motion get instant zooms (also makes screenshots deterministic). */
const reducedMotion = () => typeof matchMedia !== 'undefined' && matchMedia('(prefers-reduced-motion: reduce)').matches;

/**
 * The view as drawn: follows the controller's view with a damped spring (viewSpring.ts; the
 * configurator paper's smooth zooming) for buttons, wheel and keys, and at once for fingers
 * and with `prefers-reduced-motion`. The spring's value is React state, so every element,
 * including the constant-size controls positioned through `worldToScreen`, is laid out from
 * one view.
 */
export function usePlanView(controller: PlannerController): PlanView {
  const [view, setView] = useState<PlanView>(controller.view);
  // A layout effect, so a fit made in the planner's own layout effects is drawn before the first paint.
  useLayoutEffect(() => {
    const spring = createViewSpring(controller.view, setView);
    const unsubscribe = controller.subscribe((e) => {
      if (e.kind !== 'view') return;
      const next = controller.view;
      if (e.animate && !reducedMotion()) {
        spring.to(next);
      } else {
        spring.jump(next);
        setView(next);
      }
    });
    return () => {
      unsubscribe();
      spring.stop();
    };
  }, [controller]);
  return view;
}
