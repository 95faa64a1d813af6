import type { Vec3 } from '../core/model/lightingScene/lightingScene';
import { anyHit, type TriangleBvh } from './triangleBvh';

/**
 * What can block light in a furnished room: the objects' triangles in the reference's own
 * BVH (triangleBvh.ts) and each object's world bounds for a cheap "cannot be in the way" test.
 * The walls never occlude (the box is convex).
 */
export interface Occluders {
  bvh: TriangleBvh;
  /** Per object: [min x, y, z, max x, y, z]. */
  objectBounds: readonly Float64Array[];
}

/**
 * Offset of shadow-ray end points along their surface normals, metres: far above the
 * rounding of Float32 mesh positions in a room of metres (~1e-7 m), far below any feature.
 */
export const SHADOW_EPSILON = 1e-5;

const origin: Vec3 = [0, 0, 0];
const dir: Vec3 = [0, 0, 0];

/**
 * Is the segment from p (lifted off its surface along n) to q (lifted along nq; nq null:
 * q is a point in the air, a lamp) free of object triangles?
 */
export function segmentClear(occ: Occluders, p: Vec3, n: Vec3, q: Vec3, nq: Vec3 | null): boolean {
  for (let a = 0; a < 3; a++) {
    origin[a] = p[a] + SHADOW_EPSILON * n[a];
    dir[a] = q[a] + (nq ? SHADOW_EPSILON * nq[a] : 0) - origin[a];
  }
  return !anyHit(occ.bvh, origin, dir, 1e-9, 1 - 1e-9);
}

/**
 * Could any object lie between point p and a region with bounds b (min, max)? The
 * segments between them stay inside the box spanned by p and b; if that box misses
 * every object's bounds (grown by SHADOW_EPSILON), nothing can block them.
 */
export function mayOcclude(occ: Occluders, p: Vec3, b: ArrayLike<number>): boolean {
  const g = 2 * SHADOW_EPSILON;
  for (const o of occ.objectBounds) {
    let overlap = true;
    for (let a = 0; a < 3 && overlap; a++) {
      const lo = Math.min(p[a], b[a]);
      const hi = Math.max(p[a], b[3 + a]);
      if (hi < o[a] - g || lo > o[3 + a] + g) overlap = false;
    }
    if (overlap) return true;
  }
  return false;
}
