/** The pure parts of the browser viewer's controller: on-demand frames, bake slices, context-loss tracking, preset framing. */
import { describe, expect, it } from 'vitest';
import type { EngineProgress, RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { bakeSlice, FIRST_MS_PER_SAMPLE, SLICE_MS } from '../../../src/engines/view/bakeSlice';
import { cameraPreset } from '../../../src/engines/view/cameraPresets';
import { createBakeSlicer } from '../../../src/engines/view/createBakeSlicer';
import { createFrameScheduler } from '../../../src/engines/view/createFrameScheduler';
import { framePreset } from '../../../src/engines/view/framePreset';
import { watchContextLoss } from '../../../src/engines/view/watchContextLoss';

/** A stand-in for requestAnimationFrame / setTimeout: callbacks wait until flushed. */
function manualQueue() {
  const pending: (() => void)[] = [];
  return {
    schedule: (f: () => void) => pending.push(f),
    get size() {
      return pending.length;
    },
    flush() {
      for (const f of pending.splice(0)) f();
    },
  };
}

/** An engine whose every step costs `msPerStep(samples)` on a fake clock and advances by `samples` out of `total`. */
function fakeEngine(total: number, msPerStep: (samples: number) => number, samplesPerDraw = 8) {
  const clock = { t: 0 };
  let done = 0;
  const steps: number[] = [];
  const progress = (): EngineProgress => ({ fraction: done / total, done: done >= total, lit: done > 0 }) as EngineProgress;
  const engine = {
    get progress() {
      return progress();
    },
    settings: { samplesPerDraw } as RelightEngine['settings'],
    step(n: number) {
      steps.push(n);
      clock.t += msPerStep(n);
      done = Math.min(total, done + n);
      return progress();
    },
  };
  return { engine, clock, steps, now: () => clock.t };
}

describe('createFrameScheduler', () => {
  it('queues at most one frame however often asked, draws nothing while idle, counts frames', () => {
    const q = manualQueue();
    const seen: number[] = [];
    let draws = 0;
    const s = createFrameScheduler({ draw: () => draws++, canDraw: () => true, onFrame: (n) => seen.push(n), schedule: q.schedule });
    s.request();
    s.request();
    s.request();
    expect(q.size).toBe(1);
    q.flush();
    expect(draws).toBe(1);
    q.flush();
    expect(draws).toBe(1);
    s.request();
    q.flush();
    expect(seen).toEqual([1, 2]);
    expect(s.frames).toBe(2);
  });

  it('skips the frame while it cannot draw (context lost), and nothing after stop', () => {
    const q = manualQueue();
    let ok = false;
    let draws = 0;
    const s = createFrameScheduler({ draw: () => draws++, canDraw: () => ok, onFrame: () => {}, schedule: q.schedule });
    s.request();
    q.flush();
    expect(draws).toBe(0);
    ok = true;
    s.request();
    s.stop();
    q.flush();
    s.request();
    expect(q.size).toBe(0);
    expect(draws).toBe(0);
  });
});

describe('bakeSlice', () => {
  it('steps until the slice time is used, with as many samples as fit at the measured cost', () => {
    const f = fakeEngine(1000, (n) => n * 0.5);
    const r = bakeSlice(f.engine, FIRST_MS_PER_SAMPLE, f.now);
    // floor(12 / 1.5) = 8 samples, capped by samplesPerDraw 8; each step takes 4 ms, so three fit the 12 ms slice.
    expect(f.steps).toEqual([8, 8, 8]);
    expect(f.clock.t).toBe(SLICE_MS);
    // Running average of the cost: 1.5 → 0.7·1.5 + 0.3·0.5 = 1.2 → 0.99 → 0.843 ms per sample.
    expect(r.msPerSample).toBeCloseTo(0.843, 12);
    expect(r.progress.done).toBe(false);
  });

  it('a slow device gets one sample per step; a finished bake is not stepped', () => {
    const slow = fakeEngine(1000, (n) => n * 40);
    const r = bakeSlice(slow.engine, 40, slow.now);
    expect(slow.steps).toEqual([1]);
    expect(r.msPerSample).toBeCloseTo(40);
    const done = fakeEngine(0, () => 1);
    expect(bakeSlice(done.engine, 1, done.now).progress.done).toBe(true);
    expect(done.steps).toEqual([]);
  });
});

describe('createBakeSlicer', () => {
  it('queues slices until done, one at a time, reporting each; nothing without an engine or after stop', () => {
    const q = manualQueue();
    const f = fakeEngine(3, () => 100, 1);
    const reports: number[] = [];
    let engine: RelightEngine | null = null;
    const slicer = createBakeSlicer({ engine: () => engine, onSlice: (_e, p) => reports.push(p.fraction), onError: () => {}, defer: q.schedule, now: f.now });
    slicer.run();
    expect(reports).toEqual([]);
    engine = f.engine as unknown as RelightEngine;
    slicer.run();
    slicer.queue();
    expect(q.size).toBe(1);
    q.flush();
    q.flush();
    expect(reports.map((r) => r.toFixed(2))).toEqual(['0.33', '0.67', '1.00']);
    expect(q.size).toBe(0);
    slicer.stop();
    slicer.queue();
    expect(q.size).toBe(0);
  });

  it('a failing step is reported once and stops the slices', () => {
    const q = manualQueue();
    const errors: string[] = [];
    const engine = {
      progress: { done: false },
      settings: { samplesPerDraw: 8 },
      step: () => {
        throw new Error('GL_OUT_OF_MEMORY');
      },
    } as unknown as RelightEngine;
    createBakeSlicer({ engine: () => engine, onSlice: () => {}, onError: (m) => errors.push(m), defer: q.schedule }).run();
    expect(errors).toEqual(['Baking failed: GL_OUT_OF_MEMORY']);
    expect(q.size).toBe(0);
  });
});

describe('watchContextLoss', () => {
  it('prevents the default of a loss (asks for the context back), tracks lost/restored, stops on dispose', () => {
    const canvas = new EventTarget() as unknown as HTMLCanvasElement;
    const seen: string[] = [];
    const w = watchContextLoss(canvas, { lost: () => seen.push('lost'), restored: () => seen.push('restored') });
    const loss = new Event('webglcontextlost', { cancelable: true });
    canvas.dispatchEvent(loss);
    expect(loss.defaultPrevented).toBe(true);
    expect(w.lost).toBe(true);
    canvas.dispatchEvent(new Event('webglcontextrestored'));
    expect(w.lost).toBe(false);
    w.dispose();
    canvas.dispatchEvent(new Event('webglcontextlost', { cancelable: true }));
    expect(seen).toEqual(['lost', 'restored']);
  });
});

describe('framePreset', () => {
  const room = { width: 5, height: 2.6, depth: 4 };
  it('landscape: the preset as is', () => {
    expect(framePreset('corner', room, 1.6)).toEqual(cameraPreset('corner', room));
  });
  it('portrait: top and corner step back from the target by 1/aspect; eye height stays', () => {
    const p = framePreset('corner', room, 0.5);
    const c = cameraPreset('corner', room);
    expect(p.target).toEqual(c.target);
    p.position.forEach((v, i) => expect(v - p.target[i]).toBeCloseTo(2 * (c.position[i] - c.target[i]), 12));
    expect(framePreset('eye', room, 0.5)).toEqual(cameraPreset('eye', room));
  });
});
