import type { EngineProgress, RelightEngine } from '../relight/createRelightEngine';
import { bakeSlice, FIRST_MS_PER_SAMPLE } from './bakeSlice';

/**
 * The progressive background bake: slices of engine steps (bakeSlice) queued
 * with setTimeout until the bake is done. setTimeout, not
 * requestAnimationFrame: baking continues in a background tab's budget too,
 * and frames stay free for input. Keeps the measured cost per sample across
 * slices and bakes.
 */
export interface BakeSlicer {
  /** One slice now (a new scene: start without waiting for the queue). */
  run(): void;
  /** One slice soon, unless one is already queued. */
  queue(): void;
  stop(): void;
}

export interface BakeSlicerOptions {
  /** The engine to step, or null (none yet, or its context is lost): nothing to do. */
  engine(): RelightEngine | null;
  /** After every slice that ran, with the engine it stepped and its progress. */
  onSlice(engine: RelightEngine, progress: EngineProgress): void;
  onError(message: string): void;
  /** setTimeout(…, 0), or a test's stand-in. */
  defer?: (callback: () => void) => unknown;
  /** performance.now(), or a test's clock. */
  now?: () => number;
}

export function createBakeSlicer({ engine, onSlice, onError, defer = (f) => setTimeout(f, 0), now }: BakeSlicerOptions): BakeSlicer {
  let msPerSample = FIRST_MS_PER_SAMPLE;
  let queued = false;
  let stopped = false;
  const run = () => {
    queued = false;
    const e = engine();
    if (stopped || !e) return;
    let progress: EngineProgress;
    try {
      ({ progress, msPerSample } = bakeSlice(e, msPerSample, now));
    } catch (error) {
      onError(`Baking failed: ${(error as Error).message}`);
      return;
    }
    onSlice(e, progress);
    if (!progress.done) queue();
  };
  const queue = () => {
    if (queued || stopped) return;
    queued = true;
    defer(run);
  };
  return {
    run,
    queue,
    stop() {
      stopped = true;
    },
  };
}
