import type { PlanView } from './viewTransform';

/** Spring constants of the plan's zoom and pan (the values the planner used with React Spring; mass 1). */
export const VIEW_SPRING = { tension: 320, friction: 34 };

/** Distance and speed below which the spring is at rest and snaps onto its target (px and px/m scale units). */
const REST = 0.005;

/** Integration step: 1 ms, semi-implicit Euler, as React Spring steps its springs. */
const STEP_S = 0.001;

/** Longest frame integrated in one go (a tab in the background must not make the view jump through the target). */
const MAX_FRAME_S = 0.064;

export interface ViewSpring {
  /** Animate towards `target`, starting from where the view is now with its current speed. */
  to(target: PlanView): void;
  /** Go to `view` at once (fingers, reduced motion): no animation, speed zero. */
  jump(view: PlanView): void;
  stop(): void;
}

export interface SpringClock {
  now(): number;
  frame(callback: () => void): () => void;
}

const pageClock: SpringClock = {
  now: () => performance.now(),
  frame: (callback) => {
    const id = requestAnimationFrame(callback);
    return () => cancelAnimationFrame(id);
  },
};

const KEYS = ['scale', 'offsetX', 'offsetY'] as const;

/**
 * The plan view's damped spring, x'' = −tension·(x − target) − friction·x' per
 * component (scale, offsetX, offsetY), integrated in 1 ms steps on animation
 * frames; `onChange` gets each drawn view, and the target exactly once the
 * spring rests. Written out here (a few dozen lines) instead of React Spring,
 * which cost ~16 KiB gzip of the planner's first download for this one spring
 * (docs/benchmarks.md, "First screen").
 */
export function createViewSpring(initial: PlanView, onChange: (view: PlanView) => void, clock: SpringClock = pageClock): ViewSpring {
  const x = { scale: initial.scale, offsetX: initial.offsetX, offsetY: initial.offsetY };
  const v = { scale: 0, offsetX: 0, offsetY: 0 };
  let target: PlanView = { ...x };
  let cancel: (() => void) | null = null;
  let last = 0;

  const atRest = () => KEYS.every((k) => Math.abs(x[k] - target[k]) < REST && Math.abs(v[k]) < REST);

  const tick = () => {
    cancel = null;
    const now = clock.now();
    const steps = Math.max(1, Math.round(Math.min((now - last) / 1000, MAX_FRAME_S) / STEP_S));
    last = now;
    for (let i = 0; i < steps; i++) {
      for (const k of KEYS) {
        v[k] += (-VIEW_SPRING.tension * (x[k] - target[k]) - VIEW_SPRING.friction * v[k]) * STEP_S;
        x[k] += v[k] * STEP_S;
      }
    }
    if (atRest()) {
      for (const k of KEYS) {
        x[k] = target[k];
        v[k] = 0;
      }
      onChange({ ...target });
      return;
    }
    onChange({ ...x });
    cancel = clock.frame(tick);
  };

  return {
    to(next) {
      target = { scale: next.scale, offsetX: next.offsetX, offsetY: next.offsetY };
      // Already moving: the running frames carry on towards the new target with the speed they have.
      if (cancel) return;
      if (atRest()) {
        for (const k of KEYS) x[k] = target[k];
        onChange({ ...target });
        return;
      }
      last = clock.now();
      cancel = clock.frame(tick);
    },
    jump(view) {
      cancel?.();
      cancel = null;
      target = { scale: view.scale, offsetX: view.offsetX, offsetY: view.offsetY };
      for (const k of KEYS) {
        x[k] = target[k];
        v[k] = 0;
      }
    },
    stop() {
      cancel?.();
      cancel = null;
    },
  };
}
