/**
 * A bounding volume hierarchy over world-space triangles, written for the reference
 * only (it shares nothing with the baker's three-mesh-bvh path, so a bug there cannot
 * hide in both): median split on the longest centroid axis, at most LEAF_SIZE
 * triangles per leaf, slab tests for the boxes (Kay & Kajiya, SIGGRAPH 1986) and
 * the Möller–Trumbore ray–triangle test (J. Graphics Tools 2(1), 1997). Double precision.
 */

/** Triangles per leaf: small, so a shadow ray tests few triangles. */
const LEAF_SIZE = 4;

export interface TriangleBvh {
  /** 9 numbers per triangle: the world corners a, b, c. */
  readonly triangles: Float64Array;
  readonly triangleCount: number;
  /** 6 numbers per node: min x, y, z, max x, y, z. */
  readonly bounds: Float64Array;
  /** Per node: first child index (inner node) or first entry in `order` (leaf). */
  readonly first: Int32Array;
  /** Per node: 0 for an inner node (children first and first + 1), else the number of triangles in the leaf. */
  readonly count: Int32Array;
  /** Triangle indices in leaf order. */
  readonly order: Int32Array;
}

/** Builds the hierarchy over `triangles` (9 numbers per triangle). */
export function buildTriangleBvh(triangles: Float64Array): TriangleBvh {
  const n = triangles.length / 9;
  const centroid = new Float64Array(3 * n);
  for (let t = 0; t < n; t++) {
    for (let a = 0; a < 3; a++) centroid[3 * t + a] = (triangles[9 * t + a] + triangles[9 * t + 3 + a] + triangles[9 * t + 6 + a]) / 3;
  }
  const order = new Int32Array(n);
  for (let t = 0; t < n; t++) order[t] = t;
  // A binary tree whose leaves hold at least one triangle has at most 2n − 1 nodes.
  const maxNodes = 2 * n + 1;
  const bounds = new Float64Array(6 * maxNodes);
  const first = new Int32Array(maxNodes);
  const count = new Int32Array(maxNodes);
  let nodes = 1;
  // Explicit stack of [node, start, end) ranges of `order`.
  const stack: [number, number, number][] = [[0, 0, n]];
  while (stack.length > 0) {
    const [node, start, end] = stack.pop() as [number, number, number];
    const b = 6 * node;
    for (let a = 0; a < 3; a++) {
      bounds[b + a] = Infinity;
      bounds[b + 3 + a] = -Infinity;
    }
    const cmin = [Infinity, Infinity, Infinity];
    const cmax = [-Infinity, -Infinity, -Infinity];
    for (let k = start; k < end; k++) {
      const t = order[k];
      for (let v = 0; v < 3; v++) {
        for (let a = 0; a < 3; a++) {
          const x = triangles[9 * t + 3 * v + a];
          if (x < bounds[b + a]) bounds[b + a] = x;
          if (x > bounds[b + 3 + a]) bounds[b + 3 + a] = x;
        }
      }
      for (let a = 0; a < 3; a++) {
        const c = centroid[3 * t + a];
        if (c < cmin[a]) cmin[a] = c;
        if (c > cmax[a]) cmax[a] = c;
      }
    }
    const size = end - start;
    let axis = 0;
    for (let a = 1; a < 3; a++) if (cmax[a] - cmin[a] > cmax[axis] - cmin[axis]) axis = a;
    if (size <= LEAF_SIZE || !(cmax[axis] > cmin[axis])) {
      first[node] = start;
      count[node] = size;
      continue;
    }
    // Median split: sort the range by the centroid along the axis.
    const part = Array.from(order.subarray(start, end)).sort((p, q) => centroid[3 * p + axis] - centroid[3 * q + axis]);
    order.set(part, start);
    const mid = start + (size >> 1);
    const left = nodes;
    nodes += 2;
    first[node] = left;
    count[node] = 0;
    stack.push([left, start, mid], [left + 1, mid, end]);
  }
  return { triangles, triangleCount: n, bounds: bounds.slice(0, 6 * nodes), first: first.slice(0, nodes), count: count.slice(0, nodes), order };
}

/** Does the ray o + t·d hit the node's box for some t in [0, tMax]? (slab test) */
function hitsBox(bounds: Float64Array, node: number, o: ArrayLike<number>, inv: ArrayLike<number>, tMax: number): boolean {
  let t0 = 0;
  let t1 = tMax;
  const b = 6 * node;
  for (let a = 0; a < 3; a++) {
    let near = (bounds[b + a] - o[a]) * inv[a];
    let far = (bounds[b + 3 + a] - o[a]) * inv[a];
    if (near > far) {
      const s = near;
      near = far;
      far = s;
    }
    // NaN (0 · ∞ for a ray in the slab's plane) must not reject: compare so NaN keeps t0/t1.
    if (near > t0) t0 = near;
    if (far < t1) t1 = far;
    if (t0 > t1) return false;
  }
  return true;
}

/**
 * Ray parameter t of the hit of o + t·d with triangle tri (either side), or Infinity.
 * Möller & Trumbore 1997, without culling: the back of a single-sided surface still blocks light.
 */
export function rayTriangle(tris: Float64Array, tri: number, o: ArrayLike<number>, d: ArrayLike<number>): number {
  const k = 9 * tri;
  const ax = tris[k];
  const ay = tris[k + 1];
  const az = tris[k + 2];
  const e1x = tris[k + 3] - ax;
  const e1y = tris[k + 4] - ay;
  const e1z = tris[k + 5] - az;
  const e2x = tris[k + 6] - ax;
  const e2y = tris[k + 7] - ay;
  const e2z = tris[k + 8] - az;
  const px = d[1] * e2z - d[2] * e2y;
  const py = d[2] * e2x - d[0] * e2z;
  const pz = d[0] * e2y - d[1] * e2x;
  const det = e1x * px + e1y * py + e1z * pz;
  if (det === 0) return Infinity; // ray parallel to the triangle's plane
  const inv = 1 / det;
  const sx = o[0] - ax;
  const sy = o[1] - ay;
  const sz = o[2] - az;
  const u = (sx * px + sy * py + sz * pz) * inv;
  if (u < 0 || u > 1) return Infinity;
  const qx = sy * e1z - sz * e1y;
  const qy = sz * e1x - sx * e1z;
  const qz = sx * e1y - sy * e1x;
  const v = (d[0] * qx + d[1] * qy + d[2] * qz) * inv;
  if (v < 0 || u + v > 1) return Infinity;
  return (e2x * qx + e2y * qy + e2z * qz) * inv;
}

const stackBuffer = new Int32Array(256);
const invBuffer = new Float64Array(3);

/** Is any triangle hit by o + t·d for t in (tMin, tMax)? */
export function anyHit(bvh: TriangleBvh, o: ArrayLike<number>, d: ArrayLike<number>, tMin: number, tMax: number): boolean {
  if (bvh.triangleCount === 0) return false;
  const inv = invBuffer;
  inv[0] = 1 / d[0];
  inv[1] = 1 / d[1];
  inv[2] = 1 / d[2];
  const { bounds, first, count, order, triangles } = bvh;
  let top = 0;
  stackBuffer[top++] = 0;
  while (top > 0) {
    const node = stackBuffer[--top];
    if (!hitsBox(bounds, node, o, inv, tMax)) continue;
    const c = count[node];
    if (c === 0) {
      stackBuffer[top++] = first[node];
      stackBuffer[top++] = first[node] + 1;
      continue;
    }
    for (let k = first[node]; k < first[node] + c; k++) {
      const t = rayTriangle(triangles, order[k], o, d);
      if (t > tMin && t < tMax) return true;
    }
  }
  return false;
}

/** Nearest hit t of o + t·d in (tMin, tMax) and its triangle, or t = Infinity, triangle −1. */
export function closestHit(bvh: TriangleBvh, o: ArrayLike<number>, d: ArrayLike<number>, tMin: number, tMax: number): { t: number; triangle: number } {
  let best = Infinity;
  let triangle = -1;
  if (bvh.triangleCount === 0) return { t: best, triangle };
  const inv = [1 / d[0], 1 / d[1], 1 / d[2]];
  const { bounds, first, count, order, triangles } = bvh;
  let top = 0;
  stackBuffer[top++] = 0;
  while (top > 0) {
    const node = stackBuffer[--top];
    if (!hitsBox(bounds, node, o, inv, Math.min(tMax, best))) continue;
    const c = count[node];
    if (c === 0) {
      stackBuffer[top++] = first[node];
      stackBuffer[top++] = first[node] + 1;
      continue;
    }
    for (let k = first[node]; k < first[node] + c; k++) {
      const t = rayTriangle(triangles, order[k], o, d);
      if (t > tMin && t < tMax && t < best) {
        best = t;
        triangle = order[k];
      }
    }
  }
  return { t: best, triangle };
}
