/**
 * What every pass that sees objects needs (docs/baker.md, "Objects: passes"): the BVH traversal
 * over the objects' triangles (shaders/bvhTraversal.glsl.ts, textures named by the caller) and a
 * shadow test between a surface point and a target point. Self-contained: the sampler names and
 * the BVH texture width come in as parameters.
 */
import { bvhTraversal } from './bvhTraversal.glsl';

/** Sampler uniforms of the BVH, as every object-aware pass declares them. */
export const BVH_NODES = 'uBvhNodes';
export const BVH_TRIANGLES = 'uBvhTriangles';

/**
 * Offset of a ray's origin along its surface's normal (m): keeps the ray off the surface it leaves
 * (float32 positions of a few metres are exact to ~0.3 µm, so 0.1 mm is far above rounding and far
 * below any feature the maps resolve).
 */
export const SURFACE_OFFSET = 1e-4;

export function objectTracing(bvhWidth: number): string {
  return `${bvhTraversal({ nodes: BVH_NODES, triangles: BVH_TRIANGLES, width: bvhWidth })}
// 1 when nothing lies between the surface point p (unit normal n) and the point q, else 0. The ray
// starts SURFACE_OFFSET off the surface and stops 1e-4 of the way short of q, so q's own surface
// (an object face a lamp touches, the wall a bright patch lies on) does not block it.
float visibility(vec3 p, vec3 n, vec3 q) {
  vec3 o = p + n * ${SURFACE_OFFSET.toExponential()};
  vec3 d = q - o;
  float dist = length(d);
  if (dist < 1e-6) return 1.0;
  return bvhAnyHit(o, d / dist, dist * (1.0 - 1e-4)) ? 0.0 : 1.0;
}
`;
}
