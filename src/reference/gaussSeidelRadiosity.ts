import { ReferenceInputError } from './referenceInputError';

/** What the sweeps found: indirect illuminance and exitance per patch (RGB interleaved), sweeps run and the last relative change. */
export interface RadiositySolution {
  indirectRgb: Float64Array;
  /** M = ρ·(E_dir + E_ind) per patch, lm/m². */
  exitanceRgb: Float64Array;
  sweeps: number;
  residual: number;
}

/**
 * The radiosity system E_ind,i = Σ_j F_ij · ρ_j (E_dir,j + E_ind,j), per RGB channel, by
 * Gauss–Seidel sweeps (each patch gathers with the exitances updated so far in the sweep) until the
 * largest change of indirect illuminance in a sweep is below `tolerance` × the largest total
 * (Cohen & Wallace, "Radiosity and Realistic Image Synthesis", 1993, §5.3). `F` is the dense
 * row-major N × N form-factor matrix (row i: what patch i sees); empty when nothing reflects.
 * `label` names the solver in the error after `maxSweeps` sweeps.
 */
export function gaussSeidelRadiosity(F: Float32Array, reflectance: readonly (readonly number[])[], directRgb: Float64Array, tolerance: number, maxSweeps: number, label: string): RadiositySolution {
  const N = reflectance.length;
  const indirectRgb = new Float64Array(3 * N);
  const exitanceRgb = new Float64Array(3 * N);
  for (let i = 0; i < N; i++) for (let c = 0; c < 3; c++) exitanceRgb[3 * i + c] = reflectance[i][c] * directRgb[3 * i + c];
  let sweeps = 0;
  let residual = 0;
  let maxTotal = 0;
  for (const v of directRgb) maxTotal = Math.max(maxTotal, v);
  if (F.length === 0 || maxTotal <= 0) return { indirectRgb, exitanceRgb, sweeps, residual };
  residual = Infinity;
  const gathered = [0, 0, 0];
  while (residual > tolerance) {
    if (sweeps >= maxSweeps) throw new ReferenceInputError(`${label}: no convergence after ${maxSweeps} sweeps (relative change ${residual.toExponential(2)}); raise maxSweeps`);
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
      const rho = reflectance[i];
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
  return { indirectRgb, exitanceRgb, sweeps, residual };
}
