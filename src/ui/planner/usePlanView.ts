import { useCallback, useRef, useState } from 'react';
import { useSpring } from '@react-spring/web';
import { type PlanView, type ScreenPoint, zoomAt } from './viewTransform';

export interface PlanViewControls {
  /** The view as drawn this frame (follows the spring while it animates). */
  view: PlanView;
  /** The view the spring is heading to; gestures build on it so fast wheel turns accumulate. */
  targetRef: React.RefObject<PlanView>;
  /** Animate to a view (buttons, wheel, keyboard). */
  animateTo: (next: PlanView) => void;
  /** Jump to a view without animation (drag and pinch follow the fingers directly). */
  jumpTo: (next: PlanView) => void;
  /** Zoom by a factor about a screen point, animated. */
  zoomBy: (factor: number, anchor: ScreenPoint) => void;
}

/**
 * The plan's pan/zoom state, animated with React Spring (the configurator paper's choice for smooth
 * zooming). The spring's value is mirrored into React state so every element, including the
 * constant-size controls positioned through `worldToScreen`, is laid out from one view.
 * With `prefers-reduced-motion` the app sets `Globals.skipAnimation` and views change at once.
 */
export function usePlanView(initial: PlanView): PlanViewControls {
  const [view, setView] = useState<PlanView>(initial);
  const targetRef = useRef<PlanView>(initial);
  const [, api] = useSpring(() => ({
    ...initial,
    config: { tension: 320, friction: 34 },
    onChange: ({ value }: { value: PlanView }) => setView({ scale: value.scale, offsetX: value.offsetX, offsetY: value.offsetY }),
  }));

  const animateTo = useCallback(
    (next: PlanView) => {
      targetRef.current = next;
      void api.start({ ...next, immediate: false });
    },
    [api],
  );
  const jumpTo = useCallback(
    (next: PlanView) => {
      targetRef.current = next;
      void api.start({ ...next, immediate: true });
      setView(next);
    },
    [api],
  );
  const zoomBy = useCallback(
    (factor: number, anchor: ScreenPoint) => animateTo(zoomAt(targetRef.current, anchor, factor)),
    [animateTo],
  );
  return { view, targetRef, animateTo, jumpTo, zoomBy };
}
