/**
 * The GLSL traversal of shaders/bvhTraversal.glsl.ts on the CPU, walking the same flattened
 * textures (ObjectBvhTextures) in the same order, in double precision: `luxbox probe` uses it to
 * see objects, and the tests use it to check both the flattening and the GPU. Answers match the
 * GPU's up to float rounding (a ray grazing an edge or a tie between two triangles may differ).
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { ObjectBvhTextures, PreparedObjects } from './preparedObjects';

export interface ObjectHit {
  /** Ray parameter of the hit: the point is origin + t·dir. */
  t: number;
  /** Atlas uv of the hit point, normalised (texel centres at (i + 0.5)/width). */
  atlasUv: [number, number];
  /** The ray met the lit (front, counterclockwise) side. */
  frontFace: boolean;
}

export interface ObjectRayCaster {
  /** Nearest hit with t in (0, tMax), or null. */
  closestHit(origin: Vec3, dir: Vec3, tMax: number): ObjectHit | null;
  /** Whether any triangle lies at t in (0, tMax). */
  anyHit(origin: Vec3, dir: Vec3, tMax: number): boolean;
}

interface RawHit {
  t: number;
  triangle: number;
  u: number;
  v: number;
  det: number;
}

/** Walk the flattened BVH of `bvh` (layout: shaders/bvhTraversal.glsl.ts). */
export function traverseBvh(bvh: ObjectBvhTextures, origin: Vec3, dir: Vec3, tMax: number, anyHit: boolean): RawHit | null {
  const { nodes, triangles: tri } = bvh;
  const safe = (d: number): number => (d === 0 ? 1e-20 : Math.sign(d) * Math.max(Math.abs(d), 1e-20));
  const inv = [1 / safe(dir[0]), 1 / safe(dir[1]), 1 / safe(dir[2])];
  const boxEntry = (node: number, limit: number): number => {
    const o = node * 8;
    let entry = 0;
    let leave = limit;
    for (let a = 0; a < 3; a++) {
      const t0 = (nodes[o + a] - origin[a]) * inv[a];
      const t1 = (nodes[o + 4 + a] - origin[a]) * inv[a];
      entry = Math.max(entry, Math.min(t0, t1));
      leave = Math.min(leave, Math.max(t0, t1));
    }
    return entry <= leave ? entry : -1;
  };
  let best: RawHit | null = null;
  let tHit = tMax;
  if (boxEntry(0, tMax) < 0) return null;
  const stack: [number, number][] = [];
  let node = 0;
  for (;;) {
    const o = node * 8;
    if (nodes[o + 3] < 0) {
      const count = Math.round(-nodes[o + 3]);
      const first = Math.round(nodes[o + 7]);
      for (let k = first; k < first + count; k++) {
        const h = triangleHit(tri, k, origin, dir, tHit);
        if (h) {
          best = h;
          tHit = h.t;
          if (anyHit) return best;
        }
      }
    } else {
      const left = Math.round(nodes[o + 3]);
      const right = Math.round(nodes[o + 7]);
      const tLeft = boxEntry(left, tHit);
      const tRight = boxEntry(right, tHit);
      if (tLeft >= 0 && tRight >= 0) {
        const leftFirst = tLeft <= tRight;
        stack.push(leftFirst ? [right, tRight] : [left, tLeft]);
        node = leftFirst ? left : right;
        continue;
      }
      if (tLeft >= 0) {
        node = left;
        continue;
      }
      if (tRight >= 0) {
        node = right;
        continue;
      }
    }
    node = -1;
    while (stack.length > 0) {
      const [n, entry] = stack.pop()!;
      if (entry <= tHit) {
        node = n;
        break;
      }
    }
    if (node < 0) return best;
  }
}

/** Möller & Trumbore 1997 on texture triangle k, both faces, t in (0, tMax). */
function triangleHit(tri: Float32Array, k: number, origin: Vec3, dir: Vec3, tMax: number): RawHit | null {
  const o = 16 * k;
  const v0x = tri[o],
    v0y = tri[o + 1],
    v0z = tri[o + 2];
  const e1x = tri[o + 4],
    e1y = tri[o + 5],
    e1z = tri[o + 6];
  const e2x = tri[o + 8],
    e2y = tri[o + 9],
    e2z = tri[o + 10];
  const px = dir[1] * e2z - dir[2] * e2y;
  const py = dir[2] * e2x - dir[0] * e2z;
  const pz = dir[0] * e2y - dir[1] * e2x;
  const det = e1x * px + e1y * py + e1z * pz;
  if (det === 0) return null;
  const invDet = 1 / det;
  const sx = origin[0] - v0x,
    sy = origin[1] - v0y,
    sz = origin[2] - v0z;
  const u = (sx * px + sy * py + sz * pz) * invDet;
  if (u < 0 || u > 1) return null;
  const qx = sy * e1z - sz * e1y;
  const qy = sz * e1x - sx * e1z;
  const qz = sx * e1y - sy * e1x;
  const v = (dir[0] * qx + dir[1] * qy + dir[2] * qz) * invDet;
  if (v < 0 || u + v > 1) return null;
  const t = (e2x * qx + e2y * qy + e2z * qz) * invDet;
  return t > 0 && t < tMax ? { t, triangle: k, u, v, det } : null;
}

/** A CPU ray caster over the prepared objects, with the GLSL traversal's answers. */
export function createObjectRayCaster(prepared: PreparedObjects): ObjectRayCaster {
  const { bvh } = prepared;
  return {
    closestHit(origin, dir, tMax) {
      const h = traverseBvh(bvh, origin, dir, tMax, false);
      if (!h) return null;
      const o = 16 * h.triangle;
      const tri = bvh.triangles;
      const w0 = 1 - h.u - h.v;
      return {
        t: h.t,
        atlasUv: [w0 * tri[o + 3] + h.u * tri[o + 12] + h.v * tri[o + 14], w0 * tri[o + 7] + h.u * tri[o + 13] + h.v * tri[o + 15]],
        frontFace: h.det > 0,
      };
    },
    anyHit(origin, dir, tMax) {
      return traverseBvh(bvh, origin, dir, tMax, true) !== null;
    },
  };
}
