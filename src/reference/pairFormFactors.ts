import type { Vec3 } from '../core/model/lightingScene/lightingScene';

/** What the pair loop needs of a patch. */
export interface FormFactorPatch {
  reflectance: readonly number[];
  diameter: number;
  centroid: Vec3;
  area: number;
}

/**
 * The dense form-factor matrix (row-major N × N, Float32: 1e-7 relative is far below the methods'
 * error; empty when no patch reflects). Each pair at most once, skipped when neither reflects or
 * `apart` says they cannot see each other: `formFactor(r, e, gap)` integrates over the smaller
 * patch r (points) against the larger e (exact polygon), gap being their centroids' distance; the
 * other direction follows by reciprocity, A_r·F_re = A_e·F_er, which the discrete system then
 * keeps exactly.
 */
export function pairFormFactors(patches: readonly FormFactorPatch[], formFactor: (r: number, e: number, gap: number) => number, apart: (i: number, j: number) => boolean = () => false): Float32Array {
  const N = patches.length;
  const reflective = patches.map((p) => p.reflectance.some((c) => c > 0));
  if (!reflective.some(Boolean)) return new Float32Array(0);
  const F = new Float32Array(N * N);
  for (let i = 0; i < N; i++) {
    for (let j = i + 1; j < N; j++) {
      if (!reflective[i] && !reflective[j]) continue;
      if (apart(i, j)) continue;
      const [r, e] = patches[j].diameter < patches[i].diameter ? [j, i] : [i, j];
      const R = patches[r];
      const E = patches[e];
      const gap = Math.hypot(R.centroid[0] - E.centroid[0], R.centroid[1] - E.centroid[1], R.centroid[2] - E.centroid[2]);
      const f = formFactor(r, e, gap);
      F[r * N + e] = f;
      F[e * N + r] = (f * R.area) / E.area;
    }
  }
  return F;
}
