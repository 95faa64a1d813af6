/**
 * The always-ready bake's fence-limited slices (docs/viewer.md, "Always ready: the bake service"):
 * never more than one slice's GPU work in flight, slice size from JavaScript + GPU time; pausing,
 * holding while the user interacts, and glFence on headless-gl.
 */
import { describe, expect, it } from 'vitest';
import type { EngineProgress, RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { SLICE_MS } from '../../../src/engines/view/bakeSlice';
import { createBakeSlicer, glFence, type GpuFence } from '../../../src/engines/view/createBakeSlicer';
import { createHeadlessGL } from '../../../src/hosts/node/createHeadlessGL';
import { manualQueue } from './bakeServiceKit';

describe('fence-limited slices', () => {
  /**
   * A GPU-bound device: a step costs no JavaScript time at all (draws are queued, not run), the
   * fake GPU executes each sample in GPU_MS after the previous work, and each poll of a fence
   * advances the clock by POLL_MS. Without fences a slice could queue the whole bake at once.
   */
  const GPU_MS = 5;
  const POLL_MS = 2;
  function gpuBound(total: number) {
    const clock = { t: 0 };
    let issued = 0;
    let gpuFreeAt = 0;
    let outstanding = 0;
    let maxOutstanding = 0;
    let stepsWhileOutstanding = 0;
    const slices: number[] = [];
    let current = 0;
    const progress = () => ({ groupsDone: 0, groups: 1, fraction: issued / total, done: issued >= total, lit: true }) as EngineProgress;
    const engine = {
      get progress() {
        return progress();
      },
      settings: { samplesPerDraw: 8 } as RelightEngine['settings'],
      step(n: number) {
        if (outstanding > 0) stepsWhileOutstanding++;
        issued = Math.min(total, issued + n);
        gpuFreeAt = Math.max(gpuFreeAt, clock.t) + n * GPU_MS;
        current += n;
        return progress();
      },
    } as unknown as RelightEngine;
    const fence = (): GpuFence => {
      const at = gpuFreeAt;
      outstanding++;
      maxOutstanding = Math.max(maxOutstanding, outstanding);
      slices.push(current);
      current = 0;
      let disposed = false;
      return {
        signalled: () => {
          clock.t += POLL_MS;
          return clock.t >= at;
        },
        dispose: () => {
          if (!disposed) outstanding--;
          disposed = true;
        },
      };
    };
    return { engine, fence, clock, slices, stats: () => ({ maxOutstanding, stepsWhileOutstanding, outstanding }) };
  }

  it('never has more than one slice in flight, and sizes slices by the time until the fence signalled', () => {
    const q = manualQueue();
    const d = gpuBound(400);
    const slicer = createBakeSlicer({
      engine: () => d.engine,
      onSlice: () => {},
      onError: (m) => {
        throw new Error(m);
      },
      defer: q.defer,
      now: () => d.clock.t,
      fence: d.fence,
    });
    slicer.run();
    // A second request while the first slice is in flight only queues it behind the fence.
    slicer.run();
    slicer.queue();
    expect(slicer.inFlight).toBe(1);
    q.drain();
    expect(d.engine.progress.done).toBe(true);
    expect(d.stats()).toEqual({ maxOutstanding: 1, stepsWhileOutstanding: 0, outstanding: 0 });
    // First slice: the starting guess, 1.5 ms per sample → floor(12 / 1.5) = 8 samples. The fence then
    // reports ~5 ms per sample (GPU), so slices shrink to what fits 12 ms of GPU time: 2 samples.
    expect(d.slices[0]).toBe(8);
    const steady = d.slices.slice(-20);
    for (const n of steady) expect(n * GPU_MS).toBeLessThanOrEqual(SLICE_MS);
    expect(Math.max(...steady)).toBe(Math.floor(SLICE_MS / GPU_MS));
    // The measured cost per sample converged near the GPU's (5 ms plus the polling's granularity).
    expect(slicer.msPerSample).toBeGreaterThan(GPU_MS - 1e-9);
    expect(slicer.msPerSample).toBeLessThan(GPU_MS + POLL_MS + 1);
  });

  it('runs nothing while paused and resumes where it stopped; stop ends the polling', () => {
    const q = manualQueue();
    const d = gpuBound(40);
    const slicer = createBakeSlicer({ engine: () => d.engine, onSlice: () => {}, onError: () => {}, defer: q.defer, now: () => d.clock.t, fence: d.fence });
    slicer.run();
    slicer.setPaused(true);
    q.drain();
    const paused = d.engine.progress.fraction;
    expect(paused).toBeGreaterThan(0);
    expect(paused).toBeLessThan(1);
    slicer.run();
    slicer.queue();
    expect(q.drain()).toBe(0);
    expect(d.engine.progress.fraction).toBe(paused);
    slicer.setPaused(false);
    q.drain();
    expect(d.engine.progress.done).toBe(true);
    expect(d.stats().outstanding).toBe(0);
  });

  it('held while the user interacts: reports at once (a relight shows), steps only once the hold is over', () => {
    const q = manualQueue();
    const d = gpuBound(16);
    let hold = 500;
    const reports: number[] = [];
    const slicer = createBakeSlicer({ engine: () => d.engine, onSlice: (_e, p) => reports.push(p.fraction), onError: () => {}, defer: q.defer, now: () => d.clock.t, fence: d.fence, holdMs: () => hold });
    slicer.run();
    expect(reports).toEqual([0]);
    expect(d.engine.progress.fraction).toBe(0);
    slicer.queue(); // already waiting for the hold: no second timer
    expect(q.size).toBe(1);
    hold = 0;
    q.drain();
    expect(d.engine.progress.done).toBe(true);
  });

  it('glFence on headless-gl signals after a flush and is deleted on dispose', () => {
    const gl = createHeadlessGL();
    try {
      const f = glFence(gl)!;
      expect(f).not.toBeNull();
      // How many polls the software GPU needs depends on the machine's load: finish() then guarantees
      // the fenced work is done, so the fence must read signalled without a timing assumption.
      let polls = 0;
      while (!f.signalled() && polls < 1000) polls++;
      gl.finish();
      expect(f.signalled()).toBe(true);
      f.dispose();
      expect(gl.getError()).toBe(gl.NO_ERROR);
    } finally {
      gl.destroy();
    }
  });
});
