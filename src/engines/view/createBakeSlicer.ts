import type { EngineProgress, RelightEngine } from '../relight/RelightEngine';
import { initialSlicerState, queueSlice, runSlice } from './slicer/bakeSlicerSteps';

export { FENCE_POLL_MS, FENCE_TIMEOUT_MS } from './slicer/bakeSlicerSteps';

/** A GPU fence after a slice's commands: signalled once the GPU has executed them. */
export interface GpuFence {
  signalled(): boolean;
  dispose(): void;
}

/**
 * A fence after everything issued on `gl` so far (gl.fenceSync), polled without waiting
 * (clientWaitSync with timeout 0); null when the context cannot make one. A failed wait (a lost
 * context) counts as signalled, so the slicer never waits forever.
 */
export function glFence(gl: WebGL2RenderingContext): GpuFence | null {
  const sync = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (!sync) return null;
  gl.flush(); // without a flush the fence may never reach the GPU (WebGL 2 spec §5.27)
  return {
    signalled() {
      const r = gl.clientWaitSync(sync, 0, 0);
      return r === gl.ALREADY_SIGNALED || r === gl.CONDITION_SATISFIED || r === gl.WAIT_FAILED;
    },
    dispose: () => gl.deleteSync(sync),
  };
}

/** GPU time of the commands between begin and end (a TIME_ELAPSED query). */
export interface GpuTimer {
  begin(): void;
  end(): void;
  /** Elapsed GPU ms once available; null while pending, or when a disjoint event made it meaningless. */
  elapsedMs(): number | null;
  dispose(): void;
}

/** EXT_disjoint_timer_query_webgl2 constants (the extension object carries them; fixed by the extension's spec). */
const TIME_ELAPSED_EXT = 0x88bf;
const GPU_DISJOINT_EXT = 0x8fbb;

/**
 * A GPU timer on `gl` (EXT_disjoint_timer_query_webgl2), or null without the extension (headless-gl,
 * many mobile browsers): the slicer then paces by the fence time. Results are read without waiting
 * (QUERY_RESULT_AVAILABLE) and dropped when GPU_DISJOINT_EXT reports a disjoint event.
 */
export function glTimer(gl: WebGL2RenderingContext): GpuTimer | null {
  if (!gl.getExtension('EXT_disjoint_timer_query_webgl2')) return null;
  const query = gl.createQuery();
  if (!query) return null;
  let ended = false;
  return {
    begin: () => gl.beginQuery(TIME_ELAPSED_EXT, query),
    end() {
      gl.endQuery(TIME_ELAPSED_EXT);
      ended = true;
    },
    elapsedMs() {
      if (!ended || !gl.getQueryParameter(query, gl.QUERY_RESULT_AVAILABLE)) return null;
      const disjoint = gl.getParameter(GPU_DISJOINT_EXT) as boolean;
      const ns = gl.getQueryParameter(query, gl.QUERY_RESULT) as number;
      return disjoint ? null : ns / 1e6;
    },
    dispose: () => gl.deleteQuery(query),
  };
}

/**
 * The progressive background bake: slices of engine steps (bakeSlice) queued with setTimeout until
 * the bake is done. setTimeout, not requestAnimationFrame: frames stay free for input. With a fence
 * factory at most one slice is in flight on the GPU: after each slice a fence goes in, and the next
 * slice starts only once it has signalled (polled every FENCE_POLL_MS); the cost per sample is the
 * time from the slice's start until then (JavaScript + GPU), so the slice size follows the GPU, not
 * only the JavaScript time. With a timer factory too (glTimer: EXT_disjoint_timer_query_webgl2), the
 * cost is the slice's measured GPU time where the query has a result when the fence signals
 * (pacedMsPerSample), the fence time otherwise. Paused, it runs nothing until resumed; held (holdMs: the user is
 * interacting), it reports and waits.
 *
 * Liveness (issue 32): until the engine reports done, every slice steps at least once (bakeSlice),
 * is followed by another slice or a fence poll, and a fence is waited for at most FENCE_TIMEOUT_MS;
 * so an unpaused slicer with an unfinished bake always has a slice queued or in flight.
 *
 * The steps (slicer/bakeSlicerSteps.ts) share one SlicerState: run, step the engine, poll the fence, queue.
 */
export interface BakeSlicer {
  /** One slice now (a new scene), or right after the slice in flight; nothing while paused (it runs on resume). */
  run(): void;
  /** One slice soon, unless one is already queued or in flight. */
  queue(): void;
  setPaused(paused: boolean): void;
  readonly paused: boolean;
  /** A slice is queued or its fence has not signalled yet. */
  readonly busy: boolean;
  /** Slices whose GPU work has not finished (fenced: never more than one). */
  readonly inFlight: number;
  /** The measured cost of one sample per texel, ms (JavaScript + GPU when fenced). */
  readonly msPerSample: number;
  stop(): void;
}

export interface BakeSlicerOptions {
  /** The engine to step, or null (none yet, or its context is lost): nothing to do. */
  engine(): RelightEngine | null;
  /** After every slice that ran, with the engine it stepped, its progress and the samples it issued (0: a held slice that only reports). */
  onSlice(engine: RelightEngine, progress: EngineProgress, samples: number): void;
  onError(message: string): void;
  /** setTimeout, or a test's stand-in. */
  defer?: (callback: () => void, ms: number) => unknown;
  /** performance.now(), or a test's clock. */
  now?: () => number;
  /** A fence after the slice's GPU commands (glFence on the engine's context); absent or null: unfenced slices. */
  fence?: () => GpuFence | null;
  /** A GPU timer around each fenced slice (glTimer on the engine's context); absent or null: paced by the fence time. */
  timer?: () => GpuTimer | null;
  /**
   * Milliseconds to hold bake work back (0: go), asked before each slice: the user is
   * interacting. A held slice still reports (onSlice with the current progress, so a relight
   * shows at once) and tries again after that long.
   */
  holdMs?: () => number;
}

export function createBakeSlicer({ defer = (f, ms) => setTimeout(f, ms), now = () => performance.now(), ...rest }: BakeSlicerOptions): BakeSlicer {
  const s = initialSlicerState({ ...rest, defer, now });
  return {
    run: () => runSlice(s),
    queue: () => queueSlice(s),
    setPaused(p) {
      if (p === s.paused) return;
      s.paused = p;
      if (!s.paused && (s.again || s.options.engine()?.progress.done === false)) queueSlice(s);
    },
    get paused() {
      return s.paused;
    },
    get busy() {
      return s.queued || s.flight !== null;
    },
    get inFlight() {
      return s.flight ? 1 : 0;
    },
    get msPerSample() {
      return s.msPerSample;
    },
    stop() {
      s.stopped = true;
    },
  };
}
