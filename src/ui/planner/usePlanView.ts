import { useLayoutEffect, useState } from 'react';
import type { PlannerController } from './PlannerController';
import type { ViewSpring } from './viewSpring';
import type { PlanView } from './viewTransform';

/** Users who ask their system for less motion get instant zooms (also makes screenshots deterministic). */
const reducedMotion = () => typeof matchMedia !== 'undefined' && matchMedia('(prefers-reduced-motion: reduce)').matches;

let viewSpringModule: Promise<typeof import('./viewSpring')> | null = null;

/** React Spring is a lazy chunk (~16 KiB gzip that the first screen cannot carry; docs/benchmarks.md, "First screen"): fetched once, by whichever planner asks first. */
export function loadViewSpring(): Promise<typeof import('./viewSpring')> {
  viewSpringModule ??= import('./viewSpring');
  return viewSpringModule;
}

const whenIdle = (run: () => void) => (typeof window.requestIdleCallback === 'function' ? window.requestIdleCallback(run) : window.setTimeout(run, 200));

/**
 * The view as drawn: follows the controller's view with a damped spring (viewSpring.ts, React
 * Spring; the configurator paper's smooth zooming) for buttons, wheel and keys, and at once for
 * fingers and with `prefers-reduced-motion`. The spring's chunk is fetched in idle time after the
 * planner mounts, or by the first animated change if that comes sooner; until it is there the
 * view jumps, as it does for reduced motion. The spring's value is React state, so every element,
 * including the constant-size controls positioned through `worldToScreen`, is laid out from one
 * view.
 */
export function usePlanView(controller: PlannerController): PlanView {
  const [view, setView] = useState<PlanView>(controller.view);
  // A layout effect, so a fit made in the planner's own layout effects is drawn before the first paint.
  useLayoutEffect(() => {
    let spring: ViewSpring | null = null;
    let mounted = true;
    const prepareSpring = () => {
      loadViewSpring().then(
        (m) => {
          // Until now every change jumped, so what is drawn is the controller's view.
          if (mounted && !spring) spring = m.createViewSpring(controller.view, setView);
        },
        () => undefined, // offline or a failed chunk: the view keeps jumping, which is all it loses
      );
    };
    if (typeof window !== 'undefined') whenIdle(prepareSpring);
    const unsubscribe = controller.subscribe((e) => {
      if (e.kind !== 'view') return;
      const next = controller.view;
      const animate = e.animate && !reducedMotion();
      if (animate && spring) {
        spring.to(next);
        return;
      }
      spring?.jump(next);
      setView(next);
      if (animate) prepareSpring();
    });
    return () => {
      mounted = false;
      unsubscribe();
      spring?.stop();
    };
  }, [controller]);
  return view;
}
