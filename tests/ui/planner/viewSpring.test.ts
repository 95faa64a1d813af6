import { Globals } from '@react-spring/web';
import { describe, expect, it } from 'vitest';
import { createViewSpring, VIEW_SPRING } from '../../../src/ui/planner/viewSpring';
import type { PlanView } from '../../../src/ui/planner/viewTransform';

/**
 * React Spring's frame loop on a clock whose frames run when the test says, `ms` apart
 * (Globals.assign replaces requestAnimationFrame and the clock it reads, once for the file; the
 * spring under test is the library's own integration).
 */
let t = 0;
let pending: FrameRequestCallback | null = null;
Globals.assign({
  now: () => t,
  requestAnimationFrame: (cb: FrameRequestCallback) => {
    pending = cb;
    return 0;
  },
});
const clock = {
  /** Run frames `ms` apart until `until` ms have passed or the spring rests; returns the frames run. */
  run(ms: number, until = Infinity): number {
    let frames = 0;
    while (pending && frames * ms < until) {
      t += ms;
      const cb = pending;
      pending = null;
      cb(t);
      frames++;
    }
    return frames;
  },
  get moving() {
    return pending !== null;
  },
};

/** React Spring's frame loop (rafz) integrates 16.667 ms in the first frame after it was idle, then the time between frames, at most 64 ms. */
const FIRST_FRAME_S = 1 / 60;

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

describe('plan view spring (React Spring Controller)', () => {
  it('follows the damped oscillator in closed form (1 ms steps, first order: within 1 % of the jump) and ends exactly on the target', () => {
    const seen: PlanView[] = [];
    const spring = createViewSpring({ scale: 0, offsetX: 0, offsetY: 0 }, (v) => seen.push(v));
    // A jump of 1 in scale, 100 px in x, −40 px in y: each component on the same unit curve.
    spring.to({ scale: 1, offsetX: 100, offsetY: -40 });
    let frames = 0;
    for (const n of [5, 10, 20, 40]) {
      frames += clock.run(10, (n - frames) * 10);
      expect(frames).toBe(n);
      const v = seen.at(-1)!;
      const want = exact(FIRST_FRAME_S + (n - 1) * 0.01);
      expect(Math.abs(v.scale - want)).toBeLessThan(0.01);
      expect(Math.abs(v.offsetX / 100 - want)).toBeLessThan(0.01);
      expect(Math.abs(v.offsetY / -40 - want)).toBeLessThan(0.01);
    }
    frames += clock.run(10);
    expect(clock.moving).toBe(false);
    expect(seen.at(-1)).toEqual({ scale: 1, offsetX: 100, offsetY: -40 });
    // ζ = 0.95: it settles in about a second, without a visible overshoot.
    expect(frames * 10).toBeLessThan(1500);
    expect(Math.max(...seen.map((v) => v.offsetX))).toBeLessThan(100.5);
  });

  it('a new target while moving keeps the speed (no restart); jump goes at once and nothing moves after it', () => {
    const seen: PlanView[] = [];
    const spring = createViewSpring({ scale: 1, offsetX: 0, offsetY: 0 }, (v) => seen.push(v));
    spring.to({ scale: 1, offsetX: 100, offsetY: 0 });
    clock.run(16, 100);
    const mid = seen.at(-1)!.offsetX;
    expect(mid).toBeGreaterThan(0);
    expect(mid).toBeLessThan(100);
    spring.to({ scale: 1, offsetX: 200, offsetY: 0 });
    clock.run(16, 16);
    // Still moving forwards from where it was, not from 0, and faster than from rest at `mid`.
    const next = seen.at(-1)!.offsetX;
    expect(next).toBeGreaterThan(mid);
    expect(next - mid).toBeGreaterThan((200 - mid) * (exact(FIRST_FRAME_S) + 1e-3));
    spring.jump({ scale: 2, offsetX: -5, offsetY: 7 });
    const n = seen.length;
    clock.run(16, 160);
    expect(clock.moving).toBe(false);
    expect(seen.slice(n).every((v) => v.scale === 2 && v.offsetX === -5 && v.offsetY === 7)).toBe(true);
    // From rest at the jumped view, a target equal to it moves nothing.
    spring.to({ scale: 2, offsetX: -5, offsetY: 7 });
    clock.run(16, 160);
    expect(seen.slice(n).every((v) => v.scale === 2 && v.offsetX === -5 && v.offsetY === 7)).toBe(true);
    expect(clock.moving).toBe(false);
  });

  it('a long pause between frames (a background tab) integrates at most 64 ms at once', () => {
    const seen: PlanView[] = [];
    const spring = createViewSpring({ scale: 0, offsetX: 0, offsetY: 0 }, (v) => seen.push(v));
    spring.to({ scale: 1, offsetX: 0, offsetY: 0 });
    clock.run(5000, 10_000);
    expect(Math.abs(seen[0].scale - exact(FIRST_FRAME_S))).toBeLessThan(0.01);
    expect(Math.abs(seen[1].scale - exact(FIRST_FRAME_S + 0.064))).toBeLessThan(0.01);
    expect(seen[1].scale).toBeLessThan(exact(0.2));
    clock.run(16);
    expect(seen.at(-1)!.scale).toBe(1);
  });
});
