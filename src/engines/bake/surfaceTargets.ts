import type { FloatTarget } from './floatTarget';
import { createPingPong, type PingPong } from './pingPong';
import type { SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';

/** The render targets of one surface for one bake (all of its size, RGBA32F). */
export interface SurfaceTargets {
  layout: SurfaceLayout;
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

/**
 * Targets for a surface from the pool. Only what is read before it is written
 * starts at zero: the first running sum and the first sample accumulator
 * (every clear is a render pass of its own).
 */
export function acquireSurfaceTargets(pool: TargetPool, layout: SurfaceLayout): SurfaceTargets {
  const target = (zero = false) => pool.acquire(layout.width, layout.height, zero);
  return {
    layout,
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

export function releaseSurfaceTargets(pool: TargetPool, t: SurfaceTargets): void {
  for (const target of [t.direct, ...t.sum.targets, ...t.samples.targets, t.previous, t.raw, t.blurTemp, t.indirect, t.total]) pool.release(target);
}
