import type { RelightEngine } from '../relight/createRelightEngine';

/** Milliseconds of bake work per slice: keeps a 60 Hz frame for interaction in between. */
export const SLICE_MS = 12;
/** Starting guess of the cost of one indirect sample per texel (all six maps), refined as it runs. */
export const FIRST_MS_PER_SAMPLE = 1.5;

/**
 * One slice of background baking: engine steps until the bake is done or
 * SLICE_MS have passed. Each step takes as many samples as fit the slice at
 * the measured cost per sample (at least one, at most the engine's
 * samplesPerDraw), so a slow GPU still yields to input; the cost is a running
 * average (70 % old, 30 % new). Returns the progress and the updated cost.
 */
export function bakeSlice(
  engine: Pick<RelightEngine, 'progress' | 'step' | 'settings'>,
  msPerSample: number,
  now: () => number = () => performance.now(),
): { progress: RelightEngine['progress']; msPerSample: number } {
  const start = now();
  let p = engine.progress;
  while (!p.done && now() - start < SLICE_MS) {
    const n = Math.max(1, Math.min(engine.settings.samplesPerDraw, Math.floor(SLICE_MS / msPerSample)));
    const t = now();
    p = engine.step(n);
    msPerSample = 0.7 * msPerSample + (0.3 * (now() - t)) / n;
  }
  return { progress: p, msPerSample };
}
