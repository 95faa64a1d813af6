/**
 * The always-ready bake (docs/viewer.md, "Always ready: the bake service"): fence-limited slices
 * (never more than one slice's GPU work in flight, slice size from JavaScript + GPU time), and the
 * service on a real relight engine (headless-gl): paused while the page is hidden, resumed when
 * visible, and a new scene replaces the pending work.
 */
import { describe, expect, it } from 'vitest';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import type { EngineProgress, RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { SLICE_MS } from '../../../src/engines/view/bakeSlice';
import { createBakeService, type VisibilitySource } from '../../../src/engines/view/createBakeService';
import { createBakeSlicer, glFence, type GpuFence } from '../../../src/engines/view/createBakeSlicer';
import { createHeadlessGL } from '../../../src/hosts/node/createHeadlessGL';
import { isotropic, uniformRoom } from '../bake/bakeTestKit';

/** Blocks the thread for `ms` (a GPU behind a fence keeps working meanwhile). */
const sleep = (ms: number) => Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);

/**
 * setTimeout stand-in: callbacks wait until run one at a time (each run may queue more). With
 * `realDelays` a callback queued with a delay runs after sleeping that long, as a real timer
 * would (fence polls on a real GPU need real time to pass).
 */
function manualQueue(realDelays = false) {
  const pending: [() => void, number][] = [];
  return {
    defer: (f: () => void, ms = 0) => {
      pending.push([f, ms]);
    },
    get size() {
      return pending.length;
    },
    /** Runs queued callbacks (and those they queue) until none is left or `limit` ran; returns how many ran. */
    drain(limit = 100_000) {
      let n = 0;
      while (pending.length > 0 && n < limit) {
        const [f, ms] = pending.shift()!;
        if (realDelays && ms > 0) sleep(ms);
        f();
        n++;
      }
      return n;
    },
  };
}

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

describe('createBakeService on a real engine (headless-gl)', () => {
  const room = uniformRoom(3, 2.5, 3, 0.5);
  // One photometry object: groups are keyed by photometry identity (luminaireGroups).
  const source = isotropic(300);
  const lum = (x: number, z: number) => ({ photometry: source, position: [x, 2.3, z] as [number, number, number], yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] as [number, number, number] });
  const scene: BakeScene = { room, luminaires: [lum(1, 1), lum(2, 2)] };

  function fakePage(hidden = false) {
    const listeners = new Set<() => void>();
    const page = {
      hidden,
      addEventListener: (_type: string, l: () => void) => listeners.add(l),
      removeEventListener: (_type: string, l: () => void) => listeners.delete(l),
      set(h: boolean) {
        page.hidden = h;
        for (const l of [...listeners]) l();
      },
      get listeners() {
        return listeners.size;
      },
    };
    return page;
  }

  /** A service on its own headless-gl context (disposing the service loses that context). */
  function service(page: ReturnType<typeof fakePage>, q: ReturnType<typeof manualQueue>, lowMemory = false) {
    const gl = createHeadlessGL();
    const canvas = () => ({ getContext: () => gl, addEventListener: () => {}, removeEventListener: () => {} });
    const s = createBakeService({ quality: 'fast', visibility: page as unknown as VisibilitySource, input: null, canvas, defer: q.defer, lowMemory });
    return {
      s,
      dispose: () => {
        s.dispose();
        gl.destroy();
      },
    };
  }

  it('pauses while the page is hidden (counters and maps stay still, nothing queued) and resumes when visible', () => {
    const page = fakePage();
    const q = manualQueue(true);
    const { s, dispose } = service(page, q);
    try {
      s.setScene(scene);
      expect(s.status()).toMatchObject({ running: true, paused: false, done: false, quality: 'fast' });
      q.drain(1); // one slice: the first group's direct basis
      expect(s.status().groupBakes).toBe(1);
      page.set(true);
      expect(s.status()).toMatchObject({ paused: true, running: false });
      q.drain();
      const still = { ...s.status(), version: s.engine!.version, fraction: s.engine!.progress.fraction };
      // Nothing is left queued while hidden (no polling either), and a new request waits too.
      expect(q.size).toBe(0);
      s.setScene(scene);
      q.drain();
      expect(s.engine!.progress.fraction).toBe(still.fraction);
      expect(s.status().groupBakes).toBe(still.groupBakes);
      expect(still.done).toBe(false);
      page.set(false);
      expect(s.status().paused).toBe(false);
      q.drain();
      expect(s.status()).toMatchObject({ running: false, paused: false, done: true, groupBakes: 2 });
      expect(s.engine!.progress.done).toBe(true);
    } finally {
      dispose();
    }
    expect(page.listeners).toBe(0);
  });

  it("luminaireWeights: the scene's dimming × colour, with the overlay, and during a crossfade (1 − e)·from + e·scene (the glow follows them)", () => {
    const q = manualQueue();
    const { s, dispose } = service(fakePage(), q);
    try {
      expect(s.luminaireWeights()).toBeNull();
      const coloured: BakeScene = { ...scene, luminaires: [{ ...scene.luminaires[0], dimming: 0.5, color: [1, 0.8, 0.6] }, scene.luminaires[1]] };
      s.setScene(coloured);
      expect(s.luminaireWeights()).toEqual([
        [0.5, 0.4, 0.3],
        [1, 1, 1],
      ]);
      s.setOverlay((sc) => ({ ...sc, luminaires: sc.luminaires.map((l) => ({ ...l, dimming: 0 })) }));
      expect(s.luminaireWeights()).toEqual([
        [0, 0, 0],
        [0, 0, 0],
      ]);
      s.setOverlay(null);
      s.setFade({ from: (sc) => ({ ...sc, luminaires: sc.luminaires.map((l) => ({ ...l, dimming: 1, color: [1, 1, 1] as [number, number, number] })) }), e: 0.25 });
      const w = s.luminaireWeights()!;
      [0.75 + 0.25 * 0.5, 0.75 + 0.25 * 0.4, 0.75 + 0.25 * 0.3].forEach((v, k) => expect(w[0][k]).toBeCloseTo(v, 12));
      expect(w[1]).toEqual([1, 1, 1]);
      s.setFade(null);
    } finally {
      dispose();
    }
  });

  it('a new scene replaces the pending work: groups of the old scene not yet baked never are', () => {
    const page = fakePage();
    const q = manualQueue(true);
    const { s, dispose } = service(page, q);
    const events: string[] = [];
    s.subscribe((e) => events.push(e.type));
    try {
      // Three groups in one room; after one slice, another room with one luminaire.
      s.setScene({ room, luminaires: [lum(1, 1), lum(2, 2), lum(1.5, 0.5)] });
      q.drain(1);
      expect(s.status().groupBakes).toBe(1);
      const other: BakeScene = { room: uniformRoom(2, 2.5, 2, 0.5), luminaires: [lum(1, 1)] };
      s.setScene(other);
      q.drain();
      expect(s.engine!.progress).toMatchObject({ groups: 1, groupsDone: 1, done: true });
      // One bake for the first scene's first group, one for the new scene: the other two were cancelled.
      expect(s.status().groupBakes).toBe(2);
      expect(s.scene).toBe(other);
      // The same scene again is a relight at most: nothing is baked.
      const before = s.status();
      s.setScene({ ...other });
      q.drain();
      expect(s.status().groupBakes).toBe(before.groupBakes);
      expect(s.status().indirectSolves).toBe(before.indirectSolves);
      expect(events).toContain('slice');
    } finally {
      dispose();
    }
  });

  it('a quality change makes a fresh engine with that level and rebakes; counters run on', () => {
    const page = fakePage();
    const q = manualQueue(true);
    const { s, dispose } = service(page, q);
    const events: string[] = [];
    s.subscribe((e) => events.push(e.type));
    try {
      s.setScene(scene);
      q.drain();
      expect(s.status().groupBakes).toBe(2);
      const first = s.engine;
      s.setQuality('balanced');
      expect(events).toContain('engine');
      expect(s.engine).not.toBe(first);
      expect(s.engine!.settings.texelSize).toBe(0.05);
      q.drain();
      expect(s.status()).toMatchObject({ done: true, groupBakes: 4, quality: 'balanced' });
    } finally {
      dispose();
    }
  });

  it('light sources: the engine shows what the service was told (a relight, announced at once, no bake), also after a quality change', () => {
    const page = fakePage();
    const q = manualQueue(true);
    const { s, dispose } = service(page, q);
    const events: string[] = [];
    s.subscribe((e) => events.push(e.type));
    try {
      s.setScene(scene);
      q.drain();
      const before = s.status();
      events.length = 0;
      s.setLightSources('daylight');
      expect(events).toEqual(['slice']);
      expect(s.lightSources).toBe('daylight');
      expect(s.engine!.lightSources).toBe('daylight');
      q.drain();
      // No daylight in this scene: the luminaires are off, nothing is baked, the dark weights are solved at once (no light, no solve).
      expect(s.status().groupBakes).toBe(before.groupBakes);
      const lit = s.engine!.maps().maps.floor.total.reduce((a, b) => a + b, 0);
      expect(lit).toBe(0);
      expect(() => s.setLightSources('moon' as never)).toThrow(/not one of/);
      expect(s.lightSources).toBe('daylight');
      s.setQuality('balanced');
      expect(s.engine!.lightSources).toBe('daylight');
      s.setLightSources('both');
      q.drain();
      expect(s.engine!.maps().maps.floor.total.reduce((a, b) => a + b, 0)).toBeGreaterThan(0);
    } finally {
      dispose();
    }
  });

  it('on a low-memory device the baker pooled targets are freed once per finished bake, and the next bake still works', () => {
    for (const lowMemory of [true, false]) {
      const q = manualQueue(true);
      const { s, dispose } = service(fakePage(), q, lowMemory);
      try {
        s.setScene(scene);
        const engine = s.engine!;
        let released = 0;
        const release = engine.releaseTargets.bind(engine);
        engine.releaseTargets = () => {
          expect(engine.progress.done).toBe(true);
          released++;
          release();
        };
        q.drain();
        expect(released).toBe(lowMemory ? 1 : 0);
        // A moved luminaire: one more group, baked on freshly allocated targets.
        s.setScene({ room, luminaires: [lum(1, 1), lum(2.2, 1.8)] });
        q.drain();
        expect(s.status()).toMatchObject({ done: true, groupBakes: 3 });
        expect(released).toBe(lowMemory ? 2 : 0);
      } finally {
        dispose();
      }
    }
  });
});

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

  const room = uniformRoom(3, 2.5, 3, 0.5);
  const source = isotropic(300);
  const lum = (x: number, z: number) => ({ photometry: source, position: [x, 2.3, z] as [number, number, number], yaw: 0, pitch: 0, roll: 0, dimming: 1, color: [1, 1, 1] as [number, number, number] });
  const scene: BakeScene = { room, luminaires: [lum(1, 1), lum(2, 2)] };
  const page = { hidden: false, addEventListener: () => {}, removeEventListener: () => {} } as unknown as VisibilitySource;

  /** A service at 'fast' quality (0.1 m texels, 32 samples × 2 bounces) on its own headless-gl context, unfenced so every slice is deterministic. */
  function service(now: () => number, q: ReturnType<typeof manualQueue>) {
    const gl = createHeadlessGL();
    const canvas = () => ({ getContext: () => gl, addEventListener: () => {}, removeEventListener: () => {} });
    const s = createBakeService({ quality: 'fast', visibility: page, input: null, canvas, defer: q.defer, now, fence: null });
    return {
      s,
      dispose: () => {
        s.dispose();
        gl.destroy();
      },
    };
  }

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
