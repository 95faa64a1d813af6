/**
 * Whether something with a convex plan footprint (a rail's or an object's rectangle, a fixing
 * plate) fits in a room of any shape: the footprint inside the outline, and its top under the
 * ceiling everywhere above it. What the always-valid rules need once rooms are not boxes
 * (issue 29: nothing may stand outside the room or reach above the ceiling or a slope).
 */
import { lowestPlaneHeight } from './ceilingPlanes';
import type { Room } from './normaliseRoom';
import { distanceToSegment, orient, pointInPolygon, segmentsCrossProperly, type PlanPoint } from './planPolygon';

/** Is p strictly inside the convex polygon, farther than `tolerance` from its edges? */
function strictlyInsideConvex(p: PlanPoint, poly: readonly PlanPoint[], tolerance: number): boolean {
  let sign = 0;
  for (let i = 0; i < poly.length; i++) {
    const a = poly[i];
    const b = poly[(i + 1) % poly.length];
    const o = orient(a, b, p);
    if (distanceToSegment(p, a, b) <= tolerance) return false;
    if (sign === 0) sign = Math.sign(o);
    else if (Math.sign(o) !== sign) return false;
  }
  return true;
}

/**
 * Is the convex footprint inside the outline (touching a wall allowed, within `tolerance` m)?
 * Its corners must be inside, no wall may cross its edges, and no corner of the outline may
 * poke into it (the inner corner of an L under a rail whose ends both lie in the room).
 */
export function footprintInsideOutline(outline: readonly PlanPoint[], footprint: readonly PlanPoint[], tolerance = 1e-9): boolean {
  if (!footprint.every((p) => pointInPolygon(p, outline, tolerance))) return false;
  for (const c of outline) if (strictlyInsideConvex(c, footprint, tolerance)) return false;
  for (let i = 0; i < footprint.length; i++) {
    const a = footprint[i];
    const b = footprint[(i + 1) % footprint.length];
    for (let j = 0; j < outline.length; j++) if (segmentsCrossProperly(a, b, outline[j], outline[(j + 1) % outline.length])) return false;
  }
  return true;
}

/** The lowest ceiling over a convex footprint (m): the ceiling is concave, so it is lowest at a corner of the footprint. */
export function lowestCeilingOver(room: Room, footprint: readonly PlanPoint[]): number {
  let h = Infinity;
  for (const [x, z] of footprint) h = Math.min(h, lowestPlaneHeight(room.ceilingPlanes, x, z));
  return h;
}

/** Does a solid over a convex footprint, from the floor up to `top` metres, fit in the room? */
export function solidFitsRoom(room: Room, footprint: readonly PlanPoint[], top: number, tolerance = 1e-9): boolean {
  return footprintInsideOutline(room.corners, footprint, tolerance) && top <= lowestCeilingOver(room, footprint) + tolerance;
}
