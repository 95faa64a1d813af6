import { describe, expect, it } from 'vitest';
import { createViewSpring, VIEW_SPRING, type SpringClock } from '../../../src/ui/planner/viewSpring';
import type { PlanView } from '../../../src/ui/planner/viewTransform';

/** A clock whose frames run when the test says, `ms` apart. */
function fakeClock() {
  let t = 0;
  let pending: (() => void) | null = null;
  const clock: SpringClock = {
    now: () => t,
    frame: (cb) => {
      pending = cb;
      return () => {
        if (pending === cb) pending = null;
      };
    },
  };
  return {
    clock,
    /** Run frames `ms` apart until `until` ms have passed or the spring rests; returns the frames run. */
    run(ms: number, until = Infinity): number {
      let frames = 0;
      while (pending && frames * ms < until) {
        t += ms;
        const cb = pending;
        pending = null;
        cb();
        frames++;
      }
      return frames;
    },
    get moving() {
      return pending !== null;
    },
  };
}

/**
 * Closed form of x'' = −k(x − 1) − c·x' from x = 0 at rest (underdamped: ζ = c / 2√k = 0.95 < 1):
 * x(t) = 1 − e^(−ζω₀t)·(cos ω_d t + ζω₀/ω_d · sin ω_d t), ω₀ = √k, ω_d = ω₀√(1 − ζ²).
 */
function exact(tSeconds: number): number {
  const w0 = Math.sqrt(VIEW_SPRING.tension);
  const zeta = VIEW_SPRING.friction / (2 * w0);
  const wd = w0 * Math.sqrt(1 - zeta * zeta);
  return 1 - Math.exp(-zeta * w0 * tSeconds) * (Math.cos(wd * tSeconds) + ((zeta * w0) / wd) * Math.sin(wd * tSeconds));
}

describe('plan view spring', () => {
  it('follows the damped oscillator in closed form (semi-implicit Euler, 1 ms steps, first order: within 1 % of the jump; measured ≤ 0.6 %) and ends exactly on the target', () => {
    const c = fakeClock();
    const seen: PlanView[] = [];
    const spring = createViewSpring({ scale: 0, offsetX: 0, offsetY: 0 }, (v) => seen.push(v), c.clock);
    // A jump of 1 in scale, 100 px in x, −40 px in y: each component on the same unit curve.
    spring.to({ scale: 1, offsetX: 100, offsetY: -40 });
    for (const ms of [50, 100, 200, 400]) {
      c.run(10, ms - seen.length * 10);
      const v = seen.at(-1)!;
      const want = exact(ms / 1000);
      expect(Math.abs(v.scale - want)).toBeLessThan(0.01);
      expect(Math.abs(v.offsetX / 100 - want)).toBeLessThan(0.01);
      expect(Math.abs(v.offsetY / -40 - want)).toBeLessThan(0.01);
    }
    c.run(10);
    expect(c.moving).toBe(false);
    expect(seen.at(-1)).toEqual({ scale: 1, offsetX: 100, offsetY: -40 });
    // ζ = 0.95: it settles in about a second, without a visible overshoot.
    expect(seen.length * 10).toBeLessThan(1500);
    expect(Math.max(...seen.map((v) => v.offsetX))).toBeLessThan(100.5);
  });

  it('a new target while moving keeps the speed (no restart); jump goes at once and stops the frames', () => {
    const c = fakeClock();
    const seen: PlanView[] = [];
    const spring = createViewSpring({ scale: 1, offsetX: 0, offsetY: 0 }, (v) => seen.push(v), c.clock);
    spring.to({ scale: 1, offsetX: 100, offsetY: 0 });
    c.run(16, 100);
    const mid = seen.at(-1)!.offsetX;
    expect(mid).toBeGreaterThan(0);
    spring.to({ scale: 1, offsetX: 200, offsetY: 0 });
    c.run(16, 16);
    // Still moving forwards from where it was, not from 0.
    expect(seen.at(-1)!.offsetX).toBeGreaterThan(mid);
    spring.jump({ scale: 2, offsetX: -5, offsetY: 7 });
    expect(c.moving).toBe(false);
    // From rest at the jumped view, a target equal to it is reported at once, with no frames.
    const n = seen.length;
    spring.to({ scale: 2, offsetX: -5, offsetY: 7 });
    expect(seen.length).toBe(n + 1);
    expect(c.moving).toBe(false);
  });

  it('a long pause between frames (a background tab) integrates at most 64 ms at once', () => {
    const c = fakeClock();
    const seen: PlanView[] = [];
    const spring = createViewSpring({ scale: 0, offsetX: 0, offsetY: 0 }, (v) => seen.push(v), c.clock);
    spring.to({ scale: 1, offsetX: 0, offsetY: 0 });
    c.run(5000, 5000);
    expect(Math.abs(seen[0].scale - exact(0.064))).toBeLessThan(0.01);
    expect(seen[0].scale).toBeLessThan(exact(0.2));
  });
});
