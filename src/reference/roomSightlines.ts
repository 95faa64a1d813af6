/**
 * Line of sight inside a room of any shape, decided in plan. The room is the prism over its
 * outline cut by the floor and by the ceiling planes (flat ceiling and slopes); the space under
 * the lowest of several planes is an intersection of half-spaces, so convex. Two points inside
 * the room therefore see each other exactly when the plan projection of the segment between
 * them stays inside the outline: it must not cross a wall. The ceiling and the slopes never block
 * (a segment between two points under a convex roof stays under it), which is why a convex
 * outline needs no test at all. Written for the reference only; shares nothing with the baker.
 */
import type { Vec3 } from '../core/model/lightingScene/lightingScene';
import { segmentsCrossProperly, type PlanPoint } from '../core/room/planPolygon';

export interface RoomSightlines {
  /** Convex outline: every pair of points in the room sees each other. */
  convex: boolean;
  corners: readonly PlanPoint[];
}

/**
 * How far (m) the ends of a sight line are lifted off their surfaces along the normals, so a
 * point on a wall lies inside the outline: far above rounding in rooms of metres, far below any
 * wall length (≥ 0.1 m).
 */
export const SIGHT_EPSILON = 1e-6;

/**
 * Do p (on a surface with inward normal np) and q (on a surface with normal nq, or a point in the
 * air when nq is null) see each other? A sight line through a wall's corner exactly (measure
 * zero) counts as clear.
 */
export function sightClear(sight: RoomSightlines, p: Vec3, np: Vec3, q: Vec3, nq: Vec3 | null): boolean {
  if (sight.convex) return true;
  const a: PlanPoint = [p[0] + SIGHT_EPSILON * np[0], p[2] + SIGHT_EPSILON * np[2]];
  const b: PlanPoint = nq ? [q[0] + SIGHT_EPSILON * nq[0], q[2] + SIGHT_EPSILON * nq[2]] : [q[0], q[2]];
  const c = sight.corners;
  for (let i = 0; i < c.length; i++) {
    if (segmentsCrossProperly(a, b, c[i], c[(i + 1) % c.length])) return false;
  }
  return true;
}
