import { Controller } from '@react-spring/web';
import type { PlanView } from './viewTransform';

/** Spring constants of the plan's zoom and pan (React Spring's tension and friction; mass 1, ζ = 34 / (2√320) = 0.95). */
export const VIEW_SPRING = { tension: 320, friction: 34 };

export interface ViewSpring {
  /** Animate towards `target`, starting from where the view is now with its current speed. */
  to(target: PlanView): void;
  /** Go to `view` at once (fingers, reduced motion): no animation, speed zero. */
  jump(view: PlanView): void;
  stop(): void;
}

const values = (v: PlanView): PlanView => ({ scale: v.scale, offsetX: v.offsetX, offsetY: v.offsetY });

/**
 * The plan view's damped spring (the configurator paper's smooth zooming): a React Spring
 * Controller over scale, offsetX and offsetY, which integrates x'' = −tension·(x − target) −
 * friction·x' in 1 ms steps on animation frames (at most 64 ms per frame) and keeps its speed when
 * the target moves. `onChange` gets each drawn view, and the target exactly once it rests. This
 * module is a lazy chunk (usePlanView.ts loads it), so React Spring is not in the first screen.
 */
export function createViewSpring(initial: PlanView, onChange: (view: PlanView) => void): ViewSpring {
  const controller = new Controller<PlanView>({
    ...values(initial),
    config: VIEW_SPRING,
    onChange: (result: { value: PlanView }) => onChange(values(result.value)),
  });
  return {
    to(target) {
      void controller.start(values(target));
    },
    jump(view) {
      controller.stop();
      controller.set(values(view));
    },
    stop() {
      controller.stop();
    },
  };
}
