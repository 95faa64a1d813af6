import type { EngineProgress } from '../../relight/RelightEngine';

export interface StallWatch {
  /** After a slice: whether `limit` working slices in a row left the progress where it was (the engine should be replaced). */
  stalled(progress: EngineProgress, samples: number): boolean;
  /** The engine was replaced: counts it and starts watching afresh. */
  restarted(): void;
  /** Engines replaced so far. */
  readonly restarts: number;
}

/**
 * The bake service watches its own progress (issue 32): the slicer guarantees a step per slice and
 * a next slice until done; this guards against steps that do not move the bake (groups based,
 * fraction). A slice without samples or a finished bake does not count.
 */
export function createStallWatch(limit: number): StallWatch {
  let restarts = 0;
  let lastProgress = '';
  let stalledSlices = 0;
  return {
    stalled(progress, samples) {
      if (samples === 0 || progress.done) return false;
      const now = `${progress.groupsDone}/${progress.groups}:${progress.fraction}`;
      stalledSlices = now === lastProgress ? stalledSlices + 1 : 0;
      lastProgress = now;
      return stalledSlices >= limit;
    },
    restarted() {
      restarts++;
      stalledSlices = 0;
      lastProgress = '';
    },
    get restarts() {
      return restarts;
    },
  };
}
