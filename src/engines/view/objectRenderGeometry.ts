/**
 * The objects as the 3D view draws them: one non-indexed triangle list for all objects, read back
 * from the prepared BVH texture (PreparedObjects.bvh.triangles, layout in
 * shaders/bvhTraversal.glsl.ts: per triangle v0, e1, e2 in world metres, the atlas uv of its three
 * corners and its chart). The corners' uvs are the very ones the baker rasterised the atlas with, so
 * a fragment's uv lands on the texel that holds its light; the chart names the object
 * (PreparedObjects.charts[c].object), which picking needs (triangle → object id).
 */
import type { PreparedObjects } from '../bake/objects/preparedObjects';

export interface ObjectRenderGeometry {
  /** World x, y, z per vertex, 3 vertices per triangle (no sharing: each triangle keeps its own chart's uvs). */
  positions: Float32Array;
  /** Atlas uv per vertex, normalised (texel centres at (i + 0.5) / width). */
  uvs: Float32Array;
  /** Unit front normal per vertex (the triangle's, e1 × e2: the counterclockwise side). */
  normals: Float32Array;
  /** Index into PreparedObjects.objects per triangle. */
  objectOfTriangle: Uint32Array;
  /** Object ids in PreparedObjects.objects order. */
  ids: string[];
  triangleCount: number;
}

/** Floats per triangle in the BVH triangle texture (4 RGBA texels). */
const FLOATS_PER_TRIANGLE = 16;

export function objectRenderGeometry(prepared: PreparedObjects): ObjectRenderGeometry {
  const n = prepared.triangleCount;
  const src = prepared.bvh.triangles;
  const positions = new Float32Array(n * 9);
  const uvs = new Float32Array(n * 6);
  const normals = new Float32Array(n * 9);
  const objectOfTriangle = new Uint32Array(n);
  for (let k = 0; k < n; k++) {
    const o = k * FLOATS_PER_TRIANGLE;
    const v0 = [src[o], src[o + 1], src[o + 2]];
    const e1 = [src[o + 4], src[o + 5], src[o + 6]];
    const e2 = [src[o + 8], src[o + 9], src[o + 10]];
    const chart = src[o + 11];
    for (let a = 0; a < 3; a++) {
      positions[9 * k + a] = v0[a];
      positions[9 * k + 3 + a] = v0[a] + e1[a];
      positions[9 * k + 6 + a] = v0[a] + e2[a];
    }
    uvs.set([src[o + 3], src[o + 7], src[o + 12], src[o + 13], src[o + 14], src[o + 15]], 6 * k);
    const nx = e1[1] * e2[2] - e1[2] * e2[1];
    const ny = e1[2] * e2[0] - e1[0] * e2[2];
    const nz = e1[0] * e2[1] - e1[1] * e2[0];
    const len = Math.hypot(nx, ny, nz) || 1;
    for (let v = 0; v < 3; v++) normals.set([nx / len, ny / len, nz / len], 9 * k + 3 * v);
    const info = prepared.charts[chart];
    if (!info) throw new Error(`objectRenderGeometry: triangle ${k} names chart ${chart}, the atlas has ${prepared.charts.length}`);
    objectOfTriangle[k] = info.object;
  }
  return { positions, uvs, normals, objectOfTriangle, ids: prepared.objects.map((o) => o.id), triangleCount: n };
}
