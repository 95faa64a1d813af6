import { BOX_FACES, type Axis, type BoxFace, type PatchGrid } from './boxGeometry';
import { parallelExchangeArea, perpendicularExchangeArea } from './rectangleExchangeArea';

/**
 * Patch-to-patch form factors of the uniform box lattice, stored compactly.
 *
 * Every face of a given orientation uses the same lattice, so the factor between
 * two patches depends only on their offset along shared axes and on their
 * distances from the common edge: parallel faces need a (2nu−1)·(2nv−1) table of
 * offsets, perpendicular faces a nb·na·(2ns−1) table. Storage is O(N^1.5) instead of
 * the O(N²) of a full matrix, while each entry is still the exact rectangle-to-
 * rectangle factor (rectangleExchangeArea.ts).
 */
export interface ParallelKernel {
  kind: 'parallel';
  /** Patches along the face's u and v axes. */
  nu: number;
  nv: number;
  /** F(P→Q) for Q offset by (du, dv) patches, at [(dv + nv − 1)·(2nu − 1) + du + nu − 1]. */
  factor: Float64Array;
}

export interface PerpendicularKernel {
  kind: 'perpendicular';
  /** Patches along the shared axis, along P's axis away from the edge (nb), along Q's axis away from the edge (na). */
  ns: number;
  nb: number;
  na: number;
  /**
   * F(P→Q) for a P patch ib patches from the common edge, a Q patch ja patches from
   * it, offset by ds along the shared axis: at [(ib·na + ja)·(2ns − 1) + ds + ns − 1].
   */
  factor: Float64Array;
}

export type FaceKernel = ParallelKernel | PerpendicularKernel;

function parallelKernel(grid: PatchGrid, face: BoxFace): ParallelKernel {
  const nu = grid.count[face.uAxis];
  const nv = grid.count[face.vAxis];
  const hu = grid.size[face.uAxis];
  const hv = grid.size[face.vAxis];
  const c = grid.extent[face.axis];
  const wu = 2 * nu - 1;
  const factor = new Float64Array(wu * (2 * nv - 1));
  const area = hu * hv;
  // The factor is even in du and dv: compute one quadrant and mirror it.
  for (let dv = 0; dv < nv; dv++) {
    for (let du = 0; du < nu; du++) {
      const f = parallelExchangeArea(0, hu, 0, hv, du * hu, (du + 1) * hu, dv * hv, (dv + 1) * hv, c) / area;
      for (const sv of dv === 0 ? [0] : [-dv, dv]) {
        for (const su of du === 0 ? [0] : [-du, du]) {
          factor[(sv + nv - 1) * wu + su + nu - 1] = f;
        }
      }
    }
  }
  return { kind: 'parallel', nu, nv, factor };
}

function perpendicularKernel(grid: PatchGrid, aP: Axis, aQ: Axis): PerpendicularKernel {
  const s = (3 - aP - aQ) as Axis;
  const ns = grid.count[s];
  const nb = grid.count[aQ];
  const na = grid.count[aP];
  const hs = grid.size[s];
  const hb = grid.size[aQ];
  const ha = grid.size[aP];
  const ws = 2 * ns - 1;
  const factor = new Float64Array(nb * na * ws);
  const areaP = hs * hb;
  for (let ib = 0; ib < nb; ib++) {
    for (let ja = 0; ja < na; ja++) {
      const base = (ib * na + ja) * ws + ns - 1;
      for (let ds = 0; ds < ns; ds++) {
        const f = perpendicularExchangeArea(0, hs, ib * hb, (ib + 1) * hb, ds * hs, (ds + 1) * hs, ja * ha, (ja + 1) * ha) / areaP;
        factor[base + ds] = f;
        factor[base - ds] = f;
      }
    }
  }
  return { kind: 'perpendicular', ns, nb, na, factor };
}

/**
 * The kernel of (Q, P) from that of (P, Q): the same exchange areas A·F with the
 * roles of the two faces swapped, divided by the other patch area. Deriving it
 * instead of recomputing makes reciprocity hold to rounding, not just to the
 * cancellation error of the 16-term sums.
 */
function transposed(grid: PatchGrid, k: PerpendicularKernel, aP: Axis, aQ: Axis): PerpendicularKernel {
  const { ns, nb, na } = k;
  const ws = 2 * ns - 1;
  // In k, P's patches have area hs·size[aQ]; in the result they become Q's.
  const ratio = grid.size[aQ] / grid.size[aP];
  const factor = new Float64Array(k.factor.length);
  for (let ib = 0; ib < nb; ib++) {
    for (let ja = 0; ja < na; ja++) {
      const from = (ib * na + ja) * ws;
      const to = (ja * nb + ib) * ws;
      // The factor is even in the shared-axis offset, so no reversal is needed.
      for (let d = 0; d < ws; d++) factor[to + d] = k.factor[from + d] * ratio;
    }
  }
  return { kind: 'perpendicular', ns, nb: na, na: nb, factor };
}

/** Kernels for every ordered pair of faces (P, Q), P ≠ Q, indexed [p·6 + q]; shared between pairs of equal orientation. */
export function buildFaceKernels(grid: PatchGrid): (FaceKernel | null)[] {
  const byAxes = new Map<string, FaceKernel>();
  const kernels: (FaceKernel | null)[] = [];
  for (const P of BOX_FACES) {
    for (const Q of BOX_FACES) {
      if (P === Q) {
        kernels.push(null);
        continue;
      }
      const key = `${P.axis}${Q.axis}`;
      let k = byAxes.get(key);
      if (!k) {
        const reverse = byAxes.get(`${Q.axis}${P.axis}`);
        k = P.axis === Q.axis ? parallelKernel(grid, P) : reverse?.kind === 'perpendicular' ? transposed(grid, reverse, Q.axis, P.axis) : perpendicularKernel(grid, P.axis, Q.axis);
        byAxes.set(key, k);
      }
      kernels.push(k);
    }
  }
  return kernels;
}

/** F(patch i of face p → patch j of face q) read from the kernels (0 for p = q: a plane does not see itself). */
export function patchFormFactor(grid: PatchGrid, kernels: (FaceKernel | null)[], p: number, i: number, q: number, j: number): number {
  const k = kernels[p * 6 + q];
  if (!k) return 0;
  const P = BOX_FACES[p];
  const Q = BOX_FACES[q];
  const idxOf = (f: BoxFace, n: number): number[] => {
    const nu = grid.count[f.uAxis];
    const idx = [0, 0, 0];
    idx[f.uAxis] = n % nu;
    idx[f.vAxis] = Math.floor(n / nu);
    return idx;
  };
  const a = idxOf(P, i);
  const b = idxOf(Q, j);
  if (k.kind === 'parallel') {
    const du = b[P.uAxis] - a[P.uAxis];
    const dv = b[P.vAxis] - a[P.vAxis];
    return k.factor[(dv + k.nv - 1) * (2 * k.nu - 1) + du + k.nu - 1];
  }
  const s = 3 - P.axis - Q.axis;
  const ib = Q.side === 0 ? a[Q.axis] : k.nb - 1 - a[Q.axis];
  const ja = P.side === 0 ? b[P.axis] : k.na - 1 - b[P.axis];
  return k.factor[(ib * k.na + ja) * (2 * k.ns - 1) + b[s] - a[s] + k.ns - 1];
}
