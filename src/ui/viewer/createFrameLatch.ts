/**
 * At the console's pace with no backlog: frames arrive as fast as the bridge
 * sends them (sACN ~44 per second per universe, several universes), the view
 * relights at most once per animation frame. The latch keeps only the latest
 * frame per universe and hands the whole set over once per scheduled frame;
 * frames that arrive in between replace each other and are never queued.
 */
export type Frames = Map<number, readonly number[]>;

export interface FrameLatch {
  /** The newest channels of a universe; schedules one apply if none is pending. */
  put(universe: number, channels: readonly number[]): void;
  /** Applies now what is held (e.g. after the patch changed), without waiting for new frames. */
  reapply(): void;
  /** The latest frame per universe. */
  readonly frames: ReadonlyMap<number, readonly number[]>;
  /** Frames received and applies made since the latch was made. */
  readonly counts: { received: number; applied: number };
  dispose(): void;
}

export function createFrameLatch(
  apply: (frames: ReadonlyMap<number, readonly number[]>) => void,
  schedule: (f: () => void) => unknown = (f) => requestAnimationFrame(f),
  cancel: (handle: unknown) => void = (h) => cancelAnimationFrame(h as number),
): FrameLatch {
  const frames: Frames = new Map();
  const counts = { received: 0, applied: 0 };
  let pending: unknown = null;
  let disposed = false;
  const flush = () => {
    pending = null;
    if (disposed) return;
    counts.applied++;
    apply(frames);
  };
  return {
    put(universe, channels) {
      if (disposed) return;
      counts.received++;
      frames.set(universe, channels);
      if (pending === null) pending = schedule(flush);
    },
    reapply() {
      if (!disposed && pending === null) pending = schedule(flush);
    },
    frames,
    counts,
    dispose() {
      disposed = true;
      if (pending !== null) cancel(pending);
      pending = null;
    },
  };
}
