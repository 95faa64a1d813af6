/**
 * Slices paced by the GPU (issue #34): with a GPU timer (EXT_disjoint_timer_query_webgl2) the
 * cost per sample comes from the slice's GPU time, not from the JavaScript/fence time; without a
 * result (no extension, pending, disjoint) the fence time is the fallback. Fake clock, fake fence
 * and fake timer: the sizing is pure arithmetic, checked by hand values.
 */
import { describe, expect, it } from 'vitest';
import type { EngineProgress, RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { FIRST_MS_PER_SAMPLE, pacedMsPerSample, SLICE_MS } from '../../../src/engines/view/bakeSlice';
import { createBakeSlicer, type GpuTimer } from '../../../src/engines/view/createBakeSlicer';

describe('pacedMsPerSample', () => {
  it('averages the GPU time per sample when the timer has it, the fence time otherwise', () => {
    // 0.7 · 1.5 + 0.3 · 40 / 8 = 2.55
    expect(pacedMsPerSample(1.5, 8, { fenceMs: 400, gpuMs: 40 })).toBeCloseTo(2.55, 12);
    // no result: 0.7 · 1.5 + 0.3 · 400 / 8 = 16.05
    expect(pacedMsPerSample(1.5, 8, { fenceMs: 400, gpuMs: null })).toBeCloseTo(16.05, 12);
    expect(pacedMsPerSample(1.5, 8, { fenceMs: 400, gpuMs: Number.NaN })).toBeCloseTo(16.05, 12);
    expect(pacedMsPerSample(1.5, 0, { fenceMs: 400, gpuMs: 40 })).toBe(1.5);
  });
});

describe('createBakeSlicer with a GPU timer', () => {
  function run(timerResult: number | null) {
    const pending: (() => void)[] = [];
    const clock = { t: 0 };
    let done = 0;
    const progress = (): EngineProgress => ({ fraction: done / 1000, done: done >= 1000, lit: done > 0 }) as EngineProgress;
    const engine = {
      get progress() {
        return progress();
      },
      settings: { samplesPerDraw: 64 } as RelightEngine['settings'],
      step(n: number) {
        clock.t += 1; // JavaScript time of a step: small, the GPU work is queued
        done += n;
        return progress();
      },
    } as unknown as RelightEngine;
    const calls: string[] = [];
    let polls = 0;
    const timer = (): GpuTimer => ({
      begin: () => calls.push('begin'),
      end: () => calls.push('end'),
      elapsedMs: () => timerResult,
      dispose: () => calls.push('dispose'),
    });
    // The fence signals on its third poll, 300 ms after the slice began (a slow software GPU plus other work).
    const fence = () => ({
      signalled: () => {
        polls++;
        if (polls === 3) clock.t = 300;
        return polls >= 3;
      },
      dispose: () => {},
    });
    const slicer = createBakeSlicer({ engine: () => engine, onSlice: () => {}, onError: () => {}, defer: (f) => pending.push(f), now: () => clock.t, fence, timer });
    slicer.run();
    // Budget floor(12 / 1.5) = 8 samples in one step.
    for (let i = 0; i < 3; i++) for (const f of pending.splice(0)) f();
    return { msPerSample: slicer.msPerSample, calls };
  }

  it('sizes the next slice from the GPU time (24 ms for 8 samples), not the 300 ms until the fence', () => {
    const paced = run(24);
    expect(paced.calls.slice(0, 3)).toEqual(['begin', 'end', 'dispose']);
    // 0.7 · 1.5 + 0.3 · 24 / 8 = 1.95
    expect(paced.msPerSample).toBeCloseTo(1.95, 12);
    expect(Math.floor(SLICE_MS / paced.msPerSample)).toBe(6);
  });

  it('falls back to the fence time without a timer result', () => {
    // 0.7 · 1.5 + 0.3 · 300 / 8 = 12.3
    expect(run(null).msPerSample).toBeCloseTo(0.7 * FIRST_MS_PER_SAMPLE + (0.3 * 300) / 8, 12);
  });
});
