/**
 * Rendering on demand: `request()` queues at most one frame for the next
 * animation frame, however often it is called in between (orbit changes, new
 * maps, settings); nothing draws while idle. A frame is skipped while
 * `canDraw` says no (the display context is lost); after `stop()` nothing
 * more is queued or drawn.
 */
export interface FrameScheduler {
  request(): void;
  /** Frames drawn so far. */
  readonly frames: number;
  stop(): void;
}

export interface FrameSchedulerOptions {
  draw(): void;
  canDraw(): boolean;
  /** After each drawn frame, with the count so far. */
  onFrame(frames: number): void;
  /** requestAnimationFrame, or a test's stand-in. */
  schedule?: (callback: () => void) => unknown;
}

export function createFrameScheduler({ draw, canDraw, onFrame, schedule = requestAnimationFrame }: FrameSchedulerOptions): FrameScheduler {
  let frames = 0;
  let queued = false;
  let stopped = false;
  const frame = () => {
    queued = false;
    if (stopped || !canDraw()) return;
    draw();
    frames++;
    onFrame(frames);
  };
  return {
    request() {
      if (queued || stopped) return;
      queued = true;
      schedule(frame);
    },
    get frames() {
      return frames;
    },
    stop() {
      stopped = true;
    },
  };
}
