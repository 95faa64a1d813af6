/**
 * Where an object's mesh lies in the room: world = T(position) · Ry(yaw) · S(scale) · local,
 * with Ry the right-handed rotation about +y (counterclockwise seen from above, the same Ry as
 * the luminaires' yaw: docs/scene-format.md, "Units and frames"). The one place that turns an
 * object placement into world coordinates: the baker, the reference, the plan's outlines and
 * the 3D view all call it.
 */
import { degreesToRadians } from '../degreesToRadians';
import type { TriangleMesh } from './triangleMesh';

/** x, y, z in metres; the same tuple as core/model's Vec3 (not imported: core/model imports core/mesh, and folders may not import each other, docs/architecture.md). */
type Vec3 = [number, number, number];

export interface MeshPlacement {
  /** World position of the mesh's origin, metres. */
  readonly position: Vec3;
  /** Degrees, counterclockwise seen from above. */
  readonly yaw: number;
  /** Uniform scale (1 = the mesh's own metres). */
  readonly scale: number;
}

/** The placement as a function of one local point (x, y, z) → world [x, y, z]. */
export function placementTransform(placement: MeshPlacement): (x: number, y: number, z: number) => Vec3 {
  // Reduced before conversion: yaw·π overflows for |yaw| ≥ 5.7e307 and gave NaN vertices (issue 32).
  const t = degreesToRadians(placement.yaw);
  const c = Math.cos(t);
  const s = Math.sin(t);
  const k = placement.scale;
  const [px, py, pz] = placement.position;
  return (x, y, z) => [px + k * (c * x + s * z), py + k * y, pz + k * (-s * x + c * z)];
}

/** Every vertex of the mesh in world coordinates (x, y, z per vertex). */
export function placedPositions(mesh: TriangleMesh, placement: MeshPlacement): Float32Array {
  const transform = placementTransform(placement);
  const out = new Float32Array(mesh.positions.length);
  for (let i = 0; i < out.length; i += 3) {
    const w = transform(mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]);
    out[i] = w[0];
    out[i + 1] = w[1];
    out[i + 2] = w[2];
  }
  return out;
}

/**
 * Index of the first vertex of placed positions with a non-finite coordinate, or −1. A position or
 * scale near the double range overflows (Float32 above 3.4e38 is Infinity); every caller that takes
 * a placement from outside checks this before any bounds test, since comparisons skip NaN.
 */
export function firstNonFiniteVertex(positions: ArrayLike<number>): number {
  for (let i = 0; i < positions.length; i++) if (!Number.isFinite(positions[i])) return Math.floor(i / 3);
  return -1;
}
