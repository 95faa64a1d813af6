import type { BakeReport } from './bakeJob';

export type BakeTimings = BakeReport['timings_ms'];

export interface BakeTimer {
  /** Milliseconds per section, accumulated (the report's timings_ms). */
  readonly timings: BakeTimings;
  /** Run `f` and add its own time (children excluded) to `key`. */
  timed<T>(key: keyof BakeTimings, f: () => T): T;
}

/**
 * Timings of a bake's sections. Without `sync` no section waits for the GPU
 * (a finish per pass is a full pipeline stall); the timings then measure
 * submission, and the first read-back pays for the queued work. With `sync`
 * (settings.syncTimings, profiling) each section finishes its own GPU work.
 * Nested sections (a bounce's blend inside a step's indirect) count once: a
 * section's own time excludes its children's.
 */
export function createBakeTimer(gl: WebGL2RenderingContext, sync: boolean): BakeTimer {
  const timings: BakeTimings = { compile: 0, direct: 0, indirect: 0, blur: 0, blend: 0, readback: 0, total: 0 };
  const open: number[] = [];
  return {
    timings,
    timed(key, f) {
      // Profiling: work the enclosing section queued is its own, not this one's.
      if (sync && open.length > 0) gl.finish();
      const s = performance.now();
      open.push(0);
      try {
        const r = f();
        if (sync) gl.finish();
        return r;
      } finally {
        const elapsed = performance.now() - s;
        timings[key] += elapsed - open.pop()!;
        if (open.length) open[open.length - 1] += elapsed;
      }
    },
  };
}
