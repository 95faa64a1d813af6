import type { RelightEngine } from '../relight/RelightEngine';

/** Milliseconds of bake work per slice: keeps a 60 Hz frame for interaction in between. */
export const SLICE_MS = 12;
/** Starting guess of the cost of one indirect sample per texel (all six maps), refined as it runs. */
export const FIRST_MS_PER_SAMPLE = 1.5;

export interface SliceResult {
  progress: RelightEngine['progress'];
  /** The cost per sample after this slice (unchanged in fenced mode: the caller measures it when the fence signals). */
  msPerSample: number;
  /** Samples asked for in this slice (a step counts the samples it was asked for): at least one step's worth unless the bake was done before the slice. */
  samples: number;
  /** JavaScript time of the slice, ms. */
  ms: number;
}

/**
 * One slice of background baking.
 *
 * Unfenced (no fence sync, e.g. a context without it): engine steps until the bake is done or
 * SLICE_MS have passed; each step takes as many samples as fit the slice at the measured cost per
 * sample (at least one, at most the engine's samplesPerDraw), the cost a running average (70 % old,
 * 30 % new) of the JavaScript time of each step.
 *
 * Fenced: WebGL draws are asynchronous (Chromium queues them to the GPU process), so the JavaScript
 * time of a step says little about its GPU cost, and stepping until 12 ms of JavaScript time have
 * passed can queue seconds of GPU work on a software rasteriser: the compositor starves and input
 * waits. So a fenced slice issues a budget of samples, floor(SLICE_MS / msPerSample) (at least one
 * step), where msPerSample is measured by the caller from the slice's start until its fence
 * signalled (JavaScript + GPU time).
 *
 * Either way a slice of an unfinished bake takes **at least one step**, whatever the clock says: on
 * a loaded machine the thread can lose SLICE_MS between the slice's first clock read and its time
 * check, and a slice that then did nothing looked like a finished bake to the slicer, which stopped
 * (issue 32: a bake stuck at 59.7 % for 11 minutes). Forward progress is per slice, not per ms.
 */
export function bakeSlice(engine: Pick<RelightEngine, 'progress' | 'step' | 'settings'>, msPerSample: number, now: () => number = () => performance.now(), fenced = false): SliceResult {
  const start = now();
  let p = engine.progress;
  let samples = 0;
  const budget = Math.max(1, Math.floor(SLICE_MS / msPerSample));
  // The time and budget checks come after a step (do … while): the first step runs unconditionally.
  while (!p.done) {
    const n = Math.max(1, Math.min(engine.settings.samplesPerDraw, fenced ? budget - samples : Math.floor(SLICE_MS / msPerSample)));
    const t = now();
    p = engine.step(n);
    samples += n;
    if (!fenced) msPerSample = 0.7 * msPerSample + (0.3 * (now() - t)) / n;
    if (!(now() - start < SLICE_MS) || (fenced && samples >= budget)) break;
  }
  return { progress: p, msPerSample, samples, ms: now() - start };
}

/**
 * The cost per sample after a fenced slice: a running average (70 % old, 30 % new) of the slice's
 * cost over its samples. The cost is the GPU time of the slice's commands where a timer query
 * measured it (EXT_disjoint_timer_query_webgl2; gpuMs null: no timer, no result yet, or a
 * disjoint event spoiled it), else the time from the slice's start until its fence signalled
 * (JavaScript + GPU + the wait for the poll). GPU time is what a slice takes from the frames the
 * compositor needs; the fence time also counts the poll interval and other tabs' work.
 */
export function pacedMsPerSample(previous: number, samples: number, elapsed: { fenceMs: number; gpuMs: number | null }): number {
  if (!(samples > 0)) return previous;
  const ms = elapsed.gpuMs !== null && Number.isFinite(elapsed.gpuMs) && elapsed.gpuMs >= 0 ? elapsed.gpuMs : elapsed.fenceMs;
  return 0.7 * previous + (0.3 * ms) / samples;
}
