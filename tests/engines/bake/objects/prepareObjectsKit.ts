/** Shared by the prepareObjects tests: the test scene prepared at 5 cm texels, its charts' triangles, and point–triangle distance. */
import { prepareObjects } from '../../../../src/engines/bake/objects/prepareObjects';
import type { PreparedObjects } from '../../../../src/engines/bake/objects/preparedObjects';
import { testScene } from './objectFixtures';

export type V3 = [number, number, number];

export const objects = testScene();
export const prepared = prepareObjects(objects, { texelSize: 0.05 });
export const { atlas } = prepared;

/** The texture triangles of one chart: v0, v1, v2 (float32 as stored). */
export function chartTriangles(p: PreparedObjects): Map<number, V3[][]> {
  const out = new Map<number, V3[][]>();
  const T = p.bvh.triangles;
  for (let k = 0; k < p.triangleCount; k++) {
    const o = 16 * k;
    const v0: V3 = [T[o], T[o + 1], T[o + 2]];
    const v1: V3 = [v0[0] + T[o + 4], v0[1] + T[o + 5], v0[2] + T[o + 6]];
    const v2: V3 = [v0[0] + T[o + 8], v0[1] + T[o + 9], v0[2] + T[o + 10]];
    const chart = T[o + 11];
    if (!out.has(chart)) out.set(chart, []);
    out.get(chart)!.push([v0, v1, v2]);
  }
  return out;
}

export const sub = (a: V3, b: V3): V3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const dot = (a: V3, b: V3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** Distance from p to triangle (a, b, c) in 3D: the plane distance if p projects inside, else the nearest edge. */
export function pointTriangleDistance(p: V3, [a, b, c]: V3[]): number {
  const n = cross(sub(b, a), sub(c, a));
  const len = Math.hypot(...n);
  const h = dot(sub(p, a), n) / len;
  const q: V3 = [p[0] - (h * n[0]) / len, p[1] - (h * n[1]) / len, p[2] - (h * n[2]) / len];
  const inside = [
    [a, b],
    [b, c],
    [c, a],
  ].every(([u, v]) => dot(cross(sub(v, u), sub(q, u)), n) >= 0);
  if (inside) return Math.abs(h);
  const segment = (u: V3, v: V3): number => {
    const d = sub(v, u);
    const s = Math.min(1, Math.max(0, dot(sub(p, u), d) / dot(d, d)));
    return Math.hypot(...sub(p, [u[0] + s * d[0], u[1] + s * d[1], u[2] + s * d[2]]));
  };
  return Math.min(segment(a, b), segment(b, c), segment(c, a));
}
