import { clearTarget, createFloatTarget, deleteTarget, type FloatTarget } from './floatTarget';

/**
 * Float render targets kept between bakes of one baker. A bake uses about a
 * dozen RGBA32F targets per surface; creating them anew each time (texture
 * storage, framebuffer, ANGLE's image and render-pass objects) was a large
 * part of a warm bake on a GPU (docs/benchmarks.md "GPU"). Acquired targets
 * are zero (as new ones are) unless the caller says it overwrites every texel
 * before reading any (`zero` false): each clear is a render pass of its own.
 */
export interface TargetPool {
  acquire(width: number, height: number, zero?: boolean): FloatTarget;
  release(target: FloatTarget): void;
  /**
   * A new job starts: free targets that were not used by this job's
   * predecessor are deleted (a new room or new settings: those sizes will
   * not come back soon), so the pool never holds more than about one job.
   */
  nextJob(): void;
  /** Free targets held (tests). */
  readonly free: number;
  dispose(): void;
}

export function createTargetPool(gl: WebGL2RenderingContext, linear: boolean): TargetPool {
  const free = new Map<string, { target: FloatTarget; job: number }[]>();
  const key = (w: number, h: number) => `${w}x${h}`;
  let count = 0;
  let job = 0;
  return {
    acquire(width, height, zero = true) {
      const list = free.get(key(width, height));
      const reused = list?.pop();
      if (reused) {
        count--;
        if (zero) clearTarget(gl, reused.target);
        return reused.target;
      }
      return createFloatTarget(gl, width, height, linear);
    },
    release(target) {
      const k = key(target.width, target.height);
      let list = free.get(k);
      if (!list) free.set(k, (list = []));
      list.push({ target, job });
      count++;
    },
    nextJob() {
      job++;
      for (const [k, list] of free) {
        const stale = list.filter((e) => e.job < job - 1);
        if (stale.length === 0) continue;
        for (const e of stale) deleteTarget(gl, e.target);
        count -= stale.length;
        if (stale.length === list.length) free.delete(k);
        else
          free.set(
            k,
            list.filter((e) => e.job >= job - 1),
          );
      }
    },
    get free() {
      return count;
    },
    dispose() {
      for (const list of free.values()) for (const e of list) deleteTarget(gl, e.target);
      free.clear();
      count = 0;
    },
  };
}
