import { createDataTexture } from '../createDataTexture';
import type { PreparedObjects } from './preparedObjects';

/** The objects of a bake on the GPU: the atlas G-buffer and the BVH as RGBA32F data textures, uploaded once per bake. */
export interface ObjectPassInputs {
  prepared: PreparedObjects;
  /** G-buffer: world point (a = coverage), normal (a = chart id + 1), reflectance (a = object index + 1). */
  points: WebGLTexture;
  normals: WebGLTexture;
  reflectance: WebGLTexture;
  bvhNodes: WebGLTexture;
  bvhTriangles: WebGLTexture;
  /** Largest reflectance of any covered atlas texel, any channel. */
  maxReflectance: number;
  dispose(): void;
}

export function uploadObjectPassInputs(gl: WebGL2RenderingContext, prepared: PreparedObjects): ObjectPassInputs {
  const { atlas, bvh } = prepared;
  const gbuffer = (data: Float32Array) => createDataTexture(gl, data, atlas.width, atlas.height, 4);
  const points = gbuffer(atlas.position);
  const normals = gbuffer(atlas.normal);
  const reflectance = gbuffer(atlas.reflectance);
  const bvhNodes = createDataTexture(gl, bvh.nodes, bvh.width, bvh.nodesHeight, 4);
  const bvhTriangles = createDataTexture(gl, bvh.triangles, bvh.width, bvh.trianglesHeight, 4);
  let maxReflectance = 0;
  for (let i = 0; i < atlas.width * atlas.height; i++) {
    if (atlas.position[4 * i + 3] <= 0) continue;
    for (let c = 0; c < 3; c++) maxReflectance = Math.max(maxReflectance, atlas.reflectance[4 * i + c]);
  }
  return {
    prepared,
    points,
    normals,
    reflectance,
    bvhNodes,
    bvhTriangles,
    maxReflectance,
    dispose() {
      for (const t of [points, normals, reflectance, bvhNodes, bvhTriangles]) gl.deleteTexture(t);
    },
  };
}
