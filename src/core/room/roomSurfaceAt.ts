/**
 * Which surface of a room of any shape a point lies on (issue 29: `luxbox probe` takes points on
 * any room surface): the surface whose plane is within `tolerance` metres of the point and whose
 * polygon (less its openings) contains the point's projection, the nearest plane winning.
 */
import { distanceToSegment, pointInPolygon } from './planPolygon';
import type { Room } from './normaliseRoom';
import { roomSurfaces, type RoomSurface } from './roomSurfaces';

type Point3 = readonly [number, number, number];

export type SurfaceAt = { surface: RoomSurface; distance: number } | { surface: null; opening: { surface: RoomSurface; index: number } | null; nearest: { surface: RoomSurface; distance: number } | null };

const dot = (a: Point3, b: Point3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** The surface a point lies on, or why none: in an opening (light leaves there; no surface), or off every surface (the nearest plane whose polygon holds its projection, if any). */
export function roomSurfaceAt(room: Room, point: Point3, tolerance: number, surfaces: readonly RoomSurface[] = roomSurfaces(room)): SurfaceAt {
  let best: { surface: RoomSurface; distance: number } | null = null;
  let nearest: { surface: RoomSurface; distance: number } | null = null;
  let opening: { surface: RoomSurface; index: number } | null = null;
  for (const s of surfaces) {
    const d: Point3 = [point[0] - s.frame.origin[0], point[1] - s.frame.origin[1], point[2] - s.frame.origin[2]];
    const distance = Math.abs(dot(d, s.inward));
    const st: [number, number] = [dot(d, s.frame.u), dot(d, s.frame.v)];
    if (!s.polygons2d.some((poly) => pointInPolygon(st, poly, tolerance))) continue;
    if (!nearest || distance < nearest.distance) nearest = { surface: s, distance };
    if (distance > tolerance) continue;
    // Strictly inside an opening (more than the tolerance from its edges): no surface there.
    const hole = s.openings.findIndex((o) => pointInPolygon(st, o.polygon2d, 0) && !o.polygon2d.some((_, k) => distanceToSegment(st, o.polygon2d[k], o.polygon2d[(k + 1) % 4]) <= tolerance));
    if (hole >= 0) {
      opening = { surface: s, index: s.openings[hole].inputIndex };
      continue;
    }
    if (!best || distance < best.distance) best = { surface: s, distance };
  }
  return best ?? { surface: null, opening, nearest };
}
