import type { FloatTarget } from './floatTarget';
import { createPingPong, type PingPong } from './pingPong';
import type { SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';

/** The render targets of one receiver (a room surface or the objects' atlas) for one bake (all of its size, RGBA32F). */
export interface BounceTargets {
  width: number;
  height: number;
  /** Direct illuminance E_0 (lux). */
  direct: FloatTarget;
  /** Running sum E_1 + … + E_k of the finished bounces. */
  sum: PingPong;
  /** The bounce under way: the sum of its samples so far. */
  samples: PingPong;
  /** The last finished bounce as S·E_k (the next bounce's input once bounce ≥ 1). */
  previous: FloatTarget;
  /** Indirect before blur (sum + tail), the blur's intermediate, the final indirect and total maps. */
  raw: FloatTarget;
  blurTemp: FloatTarget;
  indirect: FloatTarget;
  total: FloatTarget;
}

/** A room surface's targets. */
export interface SurfaceTargets extends BounceTargets {
  layout: SurfaceLayout;
}

/**
 * Targets of a receiver from the pool. Only what is read before it is written
 * starts at zero: the first running sum and the first sample accumulator
 * (every clear is a render pass of its own).
 */
export function acquireBounceTargets(pool: TargetPool, width: number, height: number): BounceTargets {
  const target = (zero = false) => pool.acquire(width, height, zero);
  return {
    width,
    height,
    direct: target(),
    sum: createPingPong(target(true), target()),
    samples: createPingPong(target(true), target()),
    previous: target(),
    raw: target(),
    blurTemp: target(),
    indirect: target(),
    total: target(),
  };
}

export function acquireSurfaceTargets(pool: TargetPool, layout: SurfaceLayout): SurfaceTargets {
  return { layout, ...acquireBounceTargets(pool, layout.width, layout.height) };
}

export function releaseSurfaceTargets(pool: TargetPool, t: BounceTargets): void {
  for (const target of [t.direct, ...t.sum.targets, ...t.samples.targets, t.previous, t.raw, t.blurTemp, t.indirect, t.total]) pool.release(target);
}
