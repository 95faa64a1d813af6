/** Geometry of a mesh's parts for orienting it (orientMesh.ts): normals, signed volume, bounding box, the canonical facing of an open part. */
import type { ConnectedPart } from './connectedParts';

/** Whether an oriented part must turn so that its area-weighted normal points along + of its largest axis; the majority of the file's windings when the normals cancel. */
export function canonicalTurn(p: Float32Array, indices: Uint32Array, part: ConnectedPart): boolean {
  const sum = [0, 0, 0];
  let area = 0;
  part.triangles.forEach((t, k) => {
    const n = crossOf(p, indices, t);
    const s = part.flip![k] ? -1 : 1;
    for (let a = 0; a < 3; a++) sum[a] += s * n[a];
    area += Math.hypot(n[0], n[1], n[2]);
  });
  if (Math.hypot(sum[0], sum[1], sum[2]) > 1e-6 * area) return !canonicalFacing(sum as [number, number, number]);
  return part.flip!.filter(Boolean).length * 2 > part.flip!.length;
}

/** True when the vector's largest component (x before y before z on ties) is positive. */
export function canonicalFacing(n: readonly number[]): boolean {
  let axis = 0;
  for (let a = 1; a < 3; a++) if (Math.abs(n[a]) > Math.abs(n[axis])) axis = a;
  return n[axis] > 0;
}

export function dot(a: readonly number[], b: readonly number[]): number {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

/** Σ (v0 − c)·((v1 − c) × (v2 − c))/6 over the part's triangles as the file winds them, relative to the flip of the first: the volume with the seed's orientation. */
export function signedVolume(p: Float32Array, indices: Uint32Array, part: ConnectedPart): number {
  // Relative to a corner of the part: keeps the sum's terms small for a part far from the origin.
  const o = 3 * indices[3 * part.triangles[0]];
  const cx = p[o],
    cy = p[o + 1],
    cz = p[o + 2];
  let sum = 0;
  part.triangles.forEach((t, k) => {
    const a = 3 * indices[3 * t],
      b = 3 * indices[3 * t + 1],
      c = 3 * indices[3 * t + 2];
    const ax = p[a] - cx,
      ay = p[a + 1] - cy,
      az = p[a + 2] - cz;
    const bx = p[b] - cx,
      by = p[b + 1] - cy,
      bz = p[b + 2] - cz;
    const qx = p[c] - cx,
      qy = p[c + 1] - cy,
      qz = p[c + 2] - cz;
    const v = ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx);
    sum += part.flip![k] ? -v : v;
  });
  return sum / 6;
}

export function boxVolume(p: Float32Array, indices: Uint32Array, part: ConnectedPart): number {
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (const t of part.triangles) {
    for (let c = 0; c < 3; c++) {
      const v = 3 * indices[3 * t + c];
      for (let a = 0; a < 3; a++) {
        min[a] = Math.min(min[a], p[v + a]);
        max[a] = Math.max(max[a], p[v + a]);
      }
    }
  }
  return (max[0] - min[0]) * (max[1] - min[1]) * (max[2] - min[2]);
}

/** Unnormalised normal (e1 × e2) of triangle t as `indices` winds it. */
export function crossOf(p: Float32Array, indices: Uint32Array, t: number): [number, number, number] {
  const a = 3 * indices[3 * t],
    b = 3 * indices[3 * t + 1],
    c = 3 * indices[3 * t + 2];
  const e1x = p[b] - p[a],
    e1y = p[b + 1] - p[a + 1],
    e1z = p[b + 2] - p[a + 2];
  const e2x = p[c] - p[a],
    e2y = p[c + 1] - p[a + 1],
    e2z = p[c + 2] - p[a + 2];
  return [e1y * e2z - e1z * e2y, e1z * e2x - e1x * e2z, e1x * e2y - e1y * e2x];
}

export function unit(v: [number, number, number]): [number, number, number] | null {
  const len = Math.hypot(v[0], v[1], v[2]);
  return len > 0 && Number.isFinite(len) ? [v[0] / len, v[1] / len, v[2] / len] : null;
}
