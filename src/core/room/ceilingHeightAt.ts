import { lowestPlaneHeight } from './ceilingPlanes';
import type { Room } from './normaliseRoom';
import { pointInPolygon } from './planPolygon';

/** The ceiling height (m) over plan point (x, z): the lowest of the flat ceiling and every slope plane. */
export function ceilingHeightAt(room: Room, x: number, z: number): number {
  return lowestPlaneHeight(room.ceilingPlanes, x, z);
}

/**
 * Is the world point [x, y, z] inside the room: inside the outline (or on a wall), not below the
 * floor and not above the ceiling (within `tolerance` metres)?
 */
export function pointInsideRoom(room: Room, point: readonly [number, number, number], tolerance = 1e-9): boolean {
  const [x, y, z] = point;
  if (!(y >= -tolerance)) return false;
  if (!(y <= ceilingHeightAt(room, x, z) + tolerance)) return false;
  return pointInPolygon([x, z], room.corners, tolerance);
}
