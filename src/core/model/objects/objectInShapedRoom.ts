/**
 * Whether a placed object lies in a room of any shape (issue 29; docs/model.md "Room shape"): its
 * plan silhouette's convex hull inside the outline (footprintInsideOutline; the hull is what a
 * convex test can judge, so a non-convex piece reaching around the inner corner of an L counts as
 * reaching through it) and every vertex under the ceiling. Vertices are enough for the ceiling:
 * the room's ceiling is the lowest of planes and a triangle is flat, so a triangle whose corners
 * lie under every plane lies under every plane throughout.
 */
import { placedPositions, type MeshPlacement } from '../../mesh/placeMesh';
import type { TriangleMesh } from '../../mesh/triangleMesh';
import { ceilingHeightAt } from '../../room/ceilingHeightAt';
import { footprintInsideOutline } from '../../room/footprintInsideRoom';
import type { Room as ShapedRoom } from '../../room/normaliseRoom';
import type { PlanPoint } from '../../room/planPolygon';
import type { Room, RoomShape } from '../configuration/configuration';
import { shapedRoom, shapeProblems } from '../configuration/roomShape';
import type { NamedObject } from '../configuration/roomShapeSupport';
import { fmt, OBJECT_EPS } from './objectGeometry';

/** Convex hull of plan points, counterclockwise (Andrew's monotone chain, Inf. Proc. Letters 9(5), 1979). */
export function convexHull(points: readonly PlanPoint[]): PlanPoint[] {
  const p = [...points].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (p.length < 3) return p;
  const cross = (o: PlanPoint, a: PlanPoint, b: PlanPoint) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lower: PlanPoint[] = [];
  for (const q of p) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
    lower.push(q);
  }
  const upper: PlanPoint[] = [];
  for (let i = p.length - 1; i >= 0; i--) {
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], p[i]) <= 0) upper.pop();
    upper.push(p[i]);
  }
  return [...lower.slice(0, -1), ...upper.slice(0, -1)];
}

export type ShapedRoomMisfit = { kind: 'outline' } | { kind: 'ceiling'; top: number; ceiling: number } | null;

/** How a placed mesh fails to fit the room (outside the outline, or a vertex `top` m up where the ceiling is `ceiling` m), or null when it fits within `tolerance` m. */
export function objectMisfit(room: ShapedRoom, mesh: TriangleMesh, placement: MeshPlacement, tolerance: number): ShapedRoomMisfit {
  const placed = placedPositions(mesh, placement);
  const plan: PlanPoint[] = [];
  for (let i = 0; i < placed.length; i += 3) plan.push([placed[i], placed[i + 2]]);
  if (!footprintInsideOutline(room.corners, convexHull(plan), tolerance)) return { kind: 'outline' };
  let worst: { top: number; ceiling: number; over: number } | null = null;
  for (let i = 0; i < placed.length; i += 3) {
    const ceiling = ceilingHeightAt(room, placed[i], placed[i + 2]);
    const over = placed[i + 1] - ceiling;
    if (over > tolerance && (!worst || over > worst.over)) worst = { top: placed[i + 1], ceiling, over };
  }
  return worst ? { kind: 'ceiling', top: worst.top, ceiling: worst.ceiling } : null;
}

/**
 * validate()'s sentence for an object that does not fit a configuration's room with a shape
 * (`object-outside`: objectOutsideOutline, objectAboveSlope), or null when it fits, the room is a
 * box, or the shape breaks its own rules (then it is the room's problem, not the object's).
 */
export function configurationObjectMisfit(room: Room, mesh: TriangleMesh, placement: MeshPlacement, named: NamedObject): { message: string; key: string; params: Record<string, string | number> } | null {
  if (!room.shape || shapeProblems(room as Room & { shape: RoomShape }).length > 0) return null;
  const misfit = objectMisfit(shapedRoom(room)!, mesh, placement, OBJECT_EPS);
  if (misfit?.kind === 'outline') return { message: `${named.name} reaches outside the room's outline`, key: 'objectOutsideOutline', params: named };
  if (misfit?.kind !== 'ceiling') return null;
  const [top, ceiling] = [fmt(misfit.top), fmt(misfit.ceiling)];
  return { message: `${named.name} reaches ${top} m, above the ceiling there (${ceiling} m under a slope)`, key: 'objectAboveSlope', params: { ...named, top: Number(top), ceiling: Number(ceiling) } };
}
