import type { FloatTarget } from './floatTarget';
import type { ObjectAtlas } from './objects/preparedObjects';
import { acquireBounceTargets, acquireSurfaceTargets, releaseSurfaceTargets, type BounceTargets, type SurfaceTargets } from './surfaceTargets';
import type { SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';

/** The objects' atlas maps as shown (dilated into the empty texels around the charts). */
export interface ShownMaps {
  direct: FloatTarget;
  indirect: FloatTarget;
  total: FloatTarget;
}

/** One bake's render targets, from the baker's pool. */
export interface BakeJobTargets {
  surfaces: SurfaceTargets[];
  /** The atlas as a receiver of the bounces, and its maps as shown; null without objects. */
  atlas: BounceTargets | null;
  atlasShown: ShownMaps | null;
  /** Every receiver the bounces run over: the six surfaces, then the atlas. */
  receivers: BounceTargets[];
  release(): void;
}

/** Step 2 of a bake (startBakeJob.ts): every target it draws into, for the surfaces and the atlas. */
export function acquireBakeJobTargets(pool: TargetPool, layouts: readonly SurfaceLayout[], atlas: ObjectAtlas | null): BakeJobTargets {
  pool.nextJob();
  const surfaces = layouts.map((layout) => acquireSurfaceTargets(pool, layout));
  const atlasTargets = atlas ? acquireBounceTargets(pool, atlas.width, atlas.height) : null;
  const atlasShown = atlas ? { direct: pool.acquire(atlas.width, atlas.height), indirect: pool.acquire(atlas.width, atlas.height), total: pool.acquire(atlas.width, atlas.height) } : null;
  const receivers: BounceTargets[] = atlasTargets ? [...surfaces, atlasTargets] : surfaces;
  return {
    surfaces,
    atlas: atlasTargets,
    atlasShown,
    receivers,
    release() {
      for (const st of receivers) releaseSurfaceTargets(pool, st);
      if (atlasShown) for (const t of Object.values(atlasShown)) pool.release(t);
    },
  };
}
