import { useLayoutEffect, useState } from 'react';
import { useSpring } from '@react-spring/web';
import type { PlannerController } from './PlannerController';
import type { PlanView } from './viewTransform';

/**
 * The view as drawn: follows the controller's view with a React Spring spring (the
 * configurator paper's choice for smooth zooming) for buttons, wheel and keys, and at once
 * for fingers. The spring's value is mirrored into React state so every element, including
 * the constant-size controls positioned through `worldToScreen`, is laid out from one view.
 * With `prefers-reduced-motion` the app sets `Globals.skipAnimation` and views change at once.
 */
export function usePlanView(controller: PlannerController): PlanView {
  const [view, setView] = useState<PlanView>(controller.view);
  const [, api] = useSpring(() => ({
    ...controller.view,
    config: { tension: 320, friction: 34 },
    onChange: ({ value }: { value: PlanView }) => setView({ scale: value.scale, offsetX: value.offsetX, offsetY: value.offsetY }),
  }));
  // A layout effect, so a fit made in the planner's own layout effects is drawn before the first paint.
  useLayoutEffect(
    () =>
      controller.subscribe((e) => {
        if (e.kind !== 'view') return;
        const next = controller.view;
        void api.start({ ...next, immediate: !e.animate });
        if (!e.animate) setView(next);
      }),
    [controller, api],
  );
  return view;
}
