import type { FloatTarget } from './floatTarget';

/**
 * Two render targets used in turn: a pass reads `read` and writes `write`,
 * then `swap` makes what it wrote the next input. Float blending is not
 * available everywhere, so every accumulation in the bake is such a pair
 * (a running sum, the samples of a bounce).
 */
export interface PingPong {
  readonly read: FloatTarget;
  readonly write: FloatTarget;
  swap(): void;
  /** Take `fresh` as the new `read` and hand back the old one (a finished result kept elsewhere). */
  exchange(fresh: FloatTarget): FloatTarget;
  /** Both targets (to release them). */
  readonly targets: readonly [FloatTarget, FloatTarget];
}

export function createPingPong(read: FloatTarget, write: FloatTarget): PingPong {
  let r = read;
  let w = write;
  return {
    get read() {
      return r;
    },
    get write() {
      return w;
    },
    swap() {
      [r, w] = [w, r];
    },
    exchange(fresh) {
      const old = r;
      r = fresh;
      return old;
    },
    get targets() {
      return [r, w] as const;
    },
  };
}
