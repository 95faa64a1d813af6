/**
 * The ceiling of a room as planes over the plan: the flat ceiling y = height and one plane per
 * slope. A slope on wall i contains that wall's line at its knee height and rises at its pitch
 * into the room, y = knee + tan(pitch)·d(x, z) with d the distance from the wall's line toward
 * the room's inside (negative beyond the line). The ceiling is the lowest of all planes
 * (issue 29), so the space under it is an intersection of half-spaces: convex.
 */
import { degreesToRadians } from '../degreesToRadians';
import type { PlanPoint } from './planPolygon';

/** The plane y = c + gx·x + gz·z. */
export interface CeilingPlane {
  readonly c: number;
  readonly gx: number;
  readonly gz: number;
}

export function planeHeight(plane: CeilingPlane, x: number, z: number): number {
  return plane.c + plane.gx * x + plane.gz * z;
}

/**
 * Unit normal of wall a → b pointing into the room, in plan: the left normal for an outline of
 * positive orientation (doubleSignedArea > 0), the right one otherwise.
 */
export function inwardNormal(a: PlanPoint, b: PlanPoint, orientation: 1 | -1): [number, number] {
  const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
  const dx = (b[0] - a[0]) / len;
  const dz = (b[1] - a[1]) / len;
  return orientation > 0 ? [-dz, dx] : [dz, -dx];
}

/** The plane of a slope on the wall a → b. */
export function slopePlane(a: PlanPoint, b: PlanPoint, orientation: 1 | -1, kneeHeight: number, pitchDegrees: number): CeilingPlane {
  const [nx, nz] = inwardNormal(a, b, orientation);
  const rise = Math.tan(degreesToRadians(pitchDegrees));
  // d(x, z) = nx·(x − ax) + nz·(z − az)
  return { c: kneeHeight - rise * (nx * a[0] + nz * a[1]), gx: rise * nx, gz: rise * nz };
}

export function flatPlane(height: number): CeilingPlane {
  return { c: height, gx: 0, gz: 0 };
}

/** The ceiling height over plan point (x, z): the lowest plane. */
export function lowestPlaneHeight(planes: readonly CeilingPlane[], x: number, z: number): number {
  let h = Infinity;
  for (const p of planes) h = Math.min(h, planeHeight(p, x, z));
  return h;
}
