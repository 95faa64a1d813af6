import type { RelightEngine } from '../../relight/RelightEngine';
import { bakeSlice, FIRST_MS_PER_SAMPLE, pacedMsPerSample } from '../bakeSlice';
import type { BakeSlicerOptions, GpuFence, GpuTimer } from '../createBakeSlicer';

/** How often a slice's fence is polled, ms (browsers clamp nested timeouts to about 4 ms anyway). */
export const FENCE_POLL_MS = 2;
/**
 * Longest wait for a slice's fence, ms: then the slice counts as finished and the bake goes on. A
 * fence that never signals (a driver that drops it; WebGL 2 §5.27 promises no bound) must not stall
 * the bake; one slice's GPU work is at most a few seconds even on a software rasteriser.
 */
export const FENCE_TIMEOUT_MS = 10_000;

/** A slice whose fence has not signalled: its fence, timer, start and the samples it issued. */
interface Flight {
  fence: GpuFence;
  timer: GpuTimer | null;
  start: number;
  samples: number;
}

/** What the slicer's steps share: its options (defaults filled in) and the state they change. */
export interface SlicerState {
  options: BakeSlicerOptions & Required<Pick<BakeSlicerOptions, 'defer' | 'now'>>;
  msPerSample: number;
  queued: boolean;
  stopped: boolean;
  paused: boolean;
  /** The slice whose fence has not signalled. */
  flight: Flight | null;
  /** A run was asked for while a slice was in flight or the slicer paused. */
  again: boolean;
}

export function initialSlicerState(options: SlicerState['options']): SlicerState {
  return { options, msPerSample: FIRST_MS_PER_SAMPLE, queued: false, stopped: false, paused: false, flight: null, again: false };
}

/** One slice now: nothing while stopped; remembered while paused or fenced; only a report while held. */
export function runSlice(s: SlicerState): void {
  s.queued = false;
  if (s.stopped) return;
  if (s.paused || s.flight) {
    s.again = true;
    return;
  }
  s.again = false;
  const e = s.options.engine();
  if (!e) return;
  const hold = s.options.holdMs?.() ?? 0;
  if (hold > 0 && !e.progress.done) {
    s.options.onSlice(e, e.progress, 0);
    s.queued = true;
    s.options.defer(() => runSlice(s), hold);
    return;
  }
  stepEngine(s, e);
}

/** The slice's engine steps (timed on the GPU when fenced and a timer exists), reported, then paced. */
function stepEngine(s: SlicerState, e: RelightEngine): void {
  const { now, fence, timer } = s.options;
  const start = now();
  const fenced = fence !== undefined;
  const gpuTimer = fenced ? (timer?.() ?? null) : null;
  let r: ReturnType<typeof bakeSlice>;
  try {
    gpuTimer?.begin();
    r = bakeSlice(e, s.msPerSample, now, fenced);
    gpuTimer?.end();
  } catch (error) {
    gpuTimer?.dispose();
    s.options.onError(`Baking failed: ${(error as Error).message}`);
    return;
  }
  s.options.onSlice(e, r.progress, r.samples);
  // Done is what the engine says, never "the slice issued nothing" (issue 32: a slice that lost its
  // time to a loaded machine issued nothing and the bake stopped at 59.7 %). bakeSlice steps at
  // least once, so nothing issued means done; if not, the bake goes on.
  if (r.samples === 0) {
    gpuTimer?.dispose();
    if (!r.progress.done) queueSlice(s);
    return;
  }
  const f = fenced ? fence() : null;
  if (!f) {
    gpuTimer?.dispose();
    if (fenced) s.msPerSample = 0.7 * s.msPerSample + (0.3 * r.ms) / r.samples;
    else s.msPerSample = r.msPerSample;
    if (!r.progress.done) queueSlice(s);
    return;
  }
  s.flight = { fence: f, timer: gpuTimer, start, samples: r.samples };
  pollFence(s);
}

/** The fence in flight, polled every FENCE_POLL_MS until it signals or FENCE_TIMEOUT_MS passed. */
function pollFence(s: SlicerState): void {
  s.options.defer(() => {
    const flight = s.flight;
    if (!flight) return;
    if (s.stopped) return endFlight(s, flight);
    if (!flight.fence.signalled() && s.options.now() - flight.start < FENCE_TIMEOUT_MS) return pollFence(s);
    s.msPerSample = pacedMsPerSample(s.msPerSample, flight.samples, { fenceMs: s.options.now() - flight.start, gpuMs: flight.timer?.elapsedMs() ?? null });
    endFlight(s, flight);
    const e = s.options.engine();
    if (s.again || (e && !e.progress.done)) queueSlice(s);
  }, FENCE_POLL_MS);
}

function endFlight(s: SlicerState, flight: Flight): void {
  flight.fence.dispose();
  flight.timer?.dispose();
  s.flight = null;
}

/** One slice soon, unless one is queued; remembered while a slice is in flight or the slicer paused. */
export function queueSlice(s: SlicerState): void {
  if (s.queued || s.stopped) return;
  if (s.flight || s.paused) {
    s.again = true;
    return;
  }
  s.queued = true;
  s.options.defer(() => runSlice(s), 0);
}
