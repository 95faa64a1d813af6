/**
 * The independent answer for the BVH tests: Möller & Trumbore (1997) in double precision over every
 * placed triangle of the scene, no tree. Also says when a ray is too close to call in float32 (it
 * grazes an edge, or two triangles lie at nearly the same distance, or the hit is at tMax), so the
 * tests can leave those few rays out instead of loosening every tolerance.
 */
import { placedPositions } from '../../../../src/core/mesh/placeMesh';
import type { BakeObject } from '../../../../src/engines/bake/bakeScene';

type V3 = [number, number, number];

export interface SceneTriangles {
  count: number;
  /** 9 numbers per triangle: world corners. */
  positions: Float64Array;
}

/** Every non-degenerate world triangle of the objects (area ≥ 1e-10 m²), independent of prepareObjects. */
export function sceneTriangles(objects: readonly BakeObject[]): SceneTriangles {
  const out: number[] = [];
  for (const o of objects) {
    const p = placedPositions(o.mesh, o);
    for (let t = 0; t < o.mesh.indices.length; t += 3) {
      const c = [0, 1, 2].map((k) => Array.from(p.subarray(3 * o.mesh.indices[t + k], 3 * o.mesh.indices[t + k] + 3)));
      const e1 = c[1].map((x, a) => x - c[0][a]);
      const e2 = c[2].map((x, a) => x - c[0][a]);
      const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
      if (Math.hypot(n[0], n[1], n[2]) / 2 < 1e-10) continue;
      out.push(...c[0], ...c[1], ...c[2]);
    }
  }
  return { count: out.length / 9, positions: new Float64Array(out) };
}

export interface BruteHit {
  t: number;
  frontFace: boolean;
  triangle: number;
}

/** Möller–Trumbore on one triangle; `margin` > 0 shrinks the triangle, < 0 grows it (barycentric units). */
function hitTriangle(P: Float64Array, k: number, o: V3, d: V3, margin: number): { t: number; det: number } | null {
  const v0 = [P[9 * k], P[9 * k + 1], P[9 * k + 2]];
  const e1 = [P[9 * k + 3] - v0[0], P[9 * k + 4] - v0[1], P[9 * k + 5] - v0[2]];
  const e2 = [P[9 * k + 6] - v0[0], P[9 * k + 7] - v0[1], P[9 * k + 8] - v0[2]];
  const p = [d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]];
  const det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
  if (det === 0) return null;
  const s = [o[0] - v0[0], o[1] - v0[1], o[2] - v0[2]];
  const u = (s[0] * p[0] + s[1] * p[1] + s[2] * p[2]) / det;
  const q = [s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]];
  const v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
  if (u < margin || v < margin || 1 - u - v < margin) return null;
  return { t: (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det, det };
}

/** Closest hit with t in (0, tMax), and whether float32 rounding could change the answer. */
export function bruteForceClosest(tris: SceneTriangles, o: V3, d: V3, tMax: number): { hit: BruteHit | null; ambiguous: boolean } {
  const eps = 1e-5;
  let hit: BruteHit | null = null;
  const near: { t: number; k: number }[] = [];
  for (let k = 0; k < tris.count; k++) {
    const loose = hitTriangle(tris.positions, k, o, d, -eps);
    if (!loose || loose.t <= 0) continue;
    near.push({ t: loose.t, k });
    const exact = hitTriangle(tris.positions, k, o, d, 0);
    if (exact && exact.t > 0 && exact.t < tMax && (!hit || exact.t < hit.t)) hit = { t: exact.t, frontFace: exact.det > 0, triangle: k };
  }
  // Too close to call: another triangle grazed in front of the answer or nearly tied with it.
  const answer = hit ? hit.t : tMax;
  let ambiguous = near.some(({ t, k }) => k !== hit?.triangle && t < answer * (1 + 1e-4));
  if (hit && (Math.abs(hit.t - tMax) <= 1e-5 * tMax || hit.t < 1e-4)) ambiguous = true;
  if (hit) {
    const strict = hitTriangle(tris.positions, hit.triangle, o, d, eps);
    if (!strict) ambiguous = true;
  }
  return { hit, ambiguous };
}
