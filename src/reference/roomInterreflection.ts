import { PieceCache, pointToPatch } from './roomFormFactors';
import type { RoomPatch } from './roomPatches';
import type { RoomSightlines } from './roomSightlines';
import { ReferenceInputError } from './referenceInputError';

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
 * solved by Gauss–Seidel sweeps. F_re from the centroid — or 4 or 16 pieces — of the smaller patch
 * r of each pair to the polygon of the larger e by Lambert's contour integral times the visible
 * share of e, and F_er = F_re·A_r/A_e by reciprocity. Openings reflect nothing.
 */
export function interreflectRoom(patches: readonly RoomPatch[], sight: RoomSightlines, directRgb: Float64Array, options: { tolerance: number; maxSweeps: number }): RoomInterreflection {
  const { tolerance, maxSweeps } = options;
  let t0 = performance.now();
  const N = patches.length;
  const reflective = patches.map((p) => p.reflectance.some((c) => c > 0));
  const anyReflective = reflective.some(Boolean);
  const F = anyReflective ? new Float32Array(N * N) : new Float32Array(0);
  const cache = new PieceCache(patches);
  if (anyReflective) {
    for (let i = 0; i < N; i++) {
      for (let j = i + 1; j < N; j++) {
        if (!reflective[i] && !reflective[j]) continue;
        if (patches[i].surface === patches[j].surface) continue; // one plane: they cannot see each other
        // Integrate over the smaller patch (points) against the larger (exact polygon); the other
        // direction by reciprocity, A_i·F_ij = A_j·F_ji, which the discrete system then keeps exactly.
        const [r, e] = patches[j].diameter < patches[i].diameter ? [j, i] : [i, j];
        const R = patches[r];
        const E = patches[e];
        const gap = Math.hypot(R.centroid[0] - E.centroid[0], R.centroid[1] - E.centroid[1], R.centroid[2] - E.centroid[2]);
        let f = 0;
        if (R.diameter > MID_RECEIVER * gap) {
          for (const piece of cache.get(r, R.diameter > NEAR_RECEIVER * gap ? 2 : 1)) f += piece.area * pointToPatch(sight, piece.centroid, R.normal, E, e, cache);
          f /= R.area;
        } else {
          f = pointToPatch(sight, R.centroid, R.normal, E, e, cache);
        }
        F[r * N + e] = f;
        F[e * N + r] = (f * R.area) / E.area;
      }
    }
  }
  const formFactorMs = performance.now() - t0;

  t0 = performance.now();
  const indirectRgb = new Float64Array(3 * N);
  const exitanceRgb = new Float64Array(3 * N);
  for (let i = 0; i < N; i++) for (let c = 0; c < 3; c++) exitanceRgb[3 * i + c] = patches[i].reflectance[c] * directRgb[3 * i + c];
  let sweeps = 0;
  let residual = 0;
  let maxTotal = 0;
  for (const v of directRgb) maxTotal = Math.max(maxTotal, v);
  if (anyReflective && maxTotal > 0) {
    residual = Infinity;
    const gathered = [0, 0, 0];
    while (residual > tolerance) {
      if (sweeps >= maxSweeps) throw new ReferenceInputError(`room reference: no convergence after ${maxSweeps} sweeps (relative change ${residual.toExponential(2)}); raise maxSweeps`);
      sweeps++;
      let change = 0;
      for (let i = 0; i < N; i++) {
        gathered[0] = 0;
        gathered[1] = 0;
        gathered[2] = 0;
        const row = i * N;
        for (let j = 0; j < N; j++) {
          const f = F[row + j];
          if (f === 0) continue;
          gathered[0] += f * exitanceRgb[3 * j];
          gathered[1] += f * exitanceRgb[3 * j + 1];
          gathered[2] += f * exitanceRgb[3 * j + 2];
        }
        const rho = patches[i].reflectance;
        for (let c = 0; c < 3; c++) {
          const k = 3 * i + c;
          change = Math.max(change, Math.abs(gathered[c] - indirectRgb[k]));
          indirectRgb[k] = gathered[c];
          exitanceRgb[k] = rho[c] * (directRgb[k] + gathered[c]);
          maxTotal = Math.max(maxTotal, directRgb[k] + gathered[c]);
        }
      }
      residual = change / maxTotal;
    }
  }
  const solveMs = performance.now() - t0;
  return { indirectRgb, exitanceRgb, sweeps, residual, formFactorMs, solveMs };
}
