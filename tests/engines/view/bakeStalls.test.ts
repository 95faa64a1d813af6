/**
 * Bakes never stall (docs/viewer.md, "Always ready: the bake service"): the slicer and the service
 * finish a bake when every slice overruns its budget or a fence never signals, and an engine whose
 * steps stop moving the bake is replaced.
 */
import { describe, expect, it } from 'vitest';
import type { EngineProgress, RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { SLICE_MS } from '../../../src/engines/view/bakeSlice';
import type { VisibilitySource } from '../../../src/engines/view/createBakeService';
import { createBakeSlicer, type GpuFence } from '../../../src/engines/view/createBakeSlicer';
import { headlessBakeService, manualQueue, scene, type ManualQueue } from './bakeServiceKit';

/**
 * Issue 32: a progressive bake stopped at 59.7 % on a loaded machine: a slice that lost its time
 * budget before its first step issued nothing, and the slicer took "nothing issued" for "done".
 * Here a clock that jumps past the slice budget at every read makes every slice overrun.
 */
describe('bakes never stall', () => {
  /** A clock that advances `ms` at every read: each slice has overrun its budget before it starts. */
  const overloaded = (ms: number) => {
    const clock = { t: 0 };
    return { clock, now: () => (clock.t += ms) };
  };

  it('the slicer: every slice overruns its budget, each still steps once, and the bake finishes (fenced and not)', () => {
    for (const fenced of [true, false]) {
      const q = manualQueue();
      let issued = 0;
      const total = 50;
      const progress = () => ({ groupsDone: 1, groups: 1, fraction: issued / total, done: issued >= total, lit: true, exact: issued >= total }) as EngineProgress;
      const engine = {
        get progress() {
          return progress();
        },
        settings: { samplesPerDraw: 8 } as RelightEngine['settings'],
        step(n: number) {
          issued = Math.min(total, issued + n);
          return progress();
        },
      } as unknown as RelightEngine;
      const { now } = overloaded(5 * SLICE_MS);
      const worked: number[] = [];
      const fence = (): GpuFence => ({ signalled: () => true, dispose: () => {} });
      const slicer = createBakeSlicer({
        engine: () => engine,
        onSlice: (_e, _p, n) => worked.push(n),
        onError: (m) => {
          throw new Error(m);
        },
        defer: q.defer,
        now,
        ...(fenced ? { fence } : {}),
      });
      slicer.run();
      q.drain();
      expect(engine.progress.done).toBe(true);
      expect(slicer.busy).toBe(false);
      // One step per slice (the clock says the budget is gone after it), never a slice that issued nothing.
      expect(worked.every((n) => n >= 1)).toBe(true);
      expect(worked.length).toBeGreaterThanOrEqual(Math.ceil(total / 8));
    }
  });

  it('a fence that never signals is given up after FENCE_TIMEOUT_MS and the bake goes on', () => {
    const q = manualQueue();
    let issued = 0;
    const progress = () => ({ groupsDone: 1, groups: 1, fraction: issued / 4, done: issued >= 4, lit: true, exact: issued >= 4 }) as EngineProgress;
    const engine = {
      get progress() {
        return progress();
      },
      settings: { samplesPerDraw: 1 } as RelightEngine['settings'],
      step() {
        issued++;
        return progress();
      },
    } as unknown as RelightEngine;
    const { now } = overloaded(1000);
    const slicer = createBakeSlicer({ engine: () => engine, onSlice: () => {}, onError: () => {}, defer: q.defer, now, fence: () => ({ signalled: () => false, dispose: () => {} }) });
    slicer.run();
    q.drain();
    expect(engine.progress.done).toBe(true);
    expect(slicer.inFlight).toBe(0);
  });
  const page = { hidden: false, addEventListener: () => {}, removeEventListener: () => {} } as unknown as VisibilitySource;

  /** A service at 'fast' quality (0.1 m texels, 32 samples × 2 bounces) on its own headless-gl context, unfenced so every slice is deterministic. */
  const service = (now: () => number, q: ManualQueue) => headlessBakeService(q, { visibility: page, now, fence: null });

  it('a real headless-gl bake finishes when every slice overruns its budget: one step per slice, progress on every slice', () => {
    const q = manualQueue();
    const { clock, now } = overloaded(5 * SLICE_MS);
    const { s, dispose } = service(now, q);
    const fractions: number[] = [];
    s.subscribe((e) => {
      if (e.type === 'slice') fractions.push(e.progress.fraction);
    });
    try {
      s.setScene(scene);
      q.drain();
      expect(s.status()).toMatchObject({ running: false, done: true, groupBakes: 2, indirectSolves: 1, restarts: 0 });
      // Deterministic: 2 groups × 2 steps (issue, read back), then 32 samples × 2 bounces one sample per slice.
      expect(fractions.length).toBe(4 + 64);
      expect(fractions[fractions.length - 1]).toBe(1);
      for (let i = 1; i < fractions.length; i++) expect(fractions[i]).toBeGreaterThanOrEqual(fractions[i - 1]);
      expect(clock.t).toBeGreaterThan(68 * SLICE_MS);
    } finally {
      dispose();
    }
  });

  it('an engine whose steps stop moving the bake is replaced after STALL_SLICES slices, and the new one finishes', () => {
    const q = manualQueue();
    const { now } = overloaded(1);
    const { s, dispose } = service(now, q);
    try {
      s.setScene(scene);
      const broken = s.engine!;
      broken.step = () => broken.progress; // a step that does nothing (a wedged context, a bug)
      q.drain();
      expect(s.engine).not.toBe(broken);
      expect(s.status()).toMatchObject({ done: true, restarts: 1 });
    } finally {
      dispose();
    }
  });
});
