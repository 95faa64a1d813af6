import { PieceCache, pointToPatch } from './roomFormFactors';
import type { RoomPatch } from './roomPatches';
import type { RoomSightlines } from './roomSightlines';
import { gaussSeidelRadiosity } from './gaussSeidelRadiosity';
import { pairFormFactors } from './pairFormFactors';

/** A receiver patch larger than this fraction of the distance to the emitter averages over 16 pieces of itself, … */
const NEAR_RECEIVER = 0.6;
/** … larger than this fraction over 4 pieces, else its centroid alone (point-to-patch error ~ (size/distance)²). */
const MID_RECEIVER = 0.3;

export interface RoomInterreflection {
  /** Patch-mean indirect illuminance, lux, RGB interleaved (3 per patch). */
  indirectRgb: Float64Array;
  /** Exitance M = ρ·(E_dir + E_ind) per patch, lm/m², RGB interleaved (0 on openings). */
  exitanceRgb: Float64Array;
  sweeps: number;
  residual: number;
  formFactorMs: number;
  solveMs: number;
}

/**
 * The diffuse interreflection of a room of any shape for given patch-mean direct illuminances,
 * whatever lit them (luminaires, issue 29; daylight through windows, issue 30), by
 * piecewise-constant radiosity (Goral et al., SIGGRAPH 1984):
 *
 *   E_ind,i = Σ_j F_ij · ρ_j (E_dir,j + E_ind,j)      per RGB channel,
 *
 * solved by Gauss–Seidel sweeps (gaussSeidelRadiosity.ts, shared with the furnished box's solver). F_re from the centroid — or 4 or 16 pieces — of the smaller patch
 * r of each pair to the polygon of the larger e by Lambert's contour integral times the visible
 * share of e, and F_er = F_re·A_r/A_e by reciprocity. Openings reflect nothing.
 */
export function interreflectRoom(patches: readonly RoomPatch[], sight: RoomSightlines, directRgb: Float64Array, options: { tolerance: number; maxSweeps: number }): RoomInterreflection {
  let t0 = performance.now();
  const cache = new PieceCache(patches);
  const F = pairFormFactors(
    patches,
    (r, e, gap) => {
      const R = patches[r];
      if (R.diameter <= MID_RECEIVER * gap) return pointToPatch(sight, R.centroid, R.normal, patches[e], e, cache);
      let f = 0;
      for (const piece of cache.get(r, R.diameter > NEAR_RECEIVER * gap ? 2 : 1)) f += piece.area * pointToPatch(sight, piece.centroid, R.normal, patches[e], e, cache);
      return f / R.area;
    },
    // One plane: they cannot see each other.
    (i, j) => patches[i].surface === patches[j].surface,
  );
  const formFactorMs = performance.now() - t0;
  t0 = performance.now();
  const reflectance = patches.map((p) => p.reflectance);
  const solution = gaussSeidelRadiosity(F, reflectance, directRgb, options.tolerance, options.maxSweeps, 'room reference');
  return { ...solution, formFactorMs, solveMs: performance.now() - t0 };
}
