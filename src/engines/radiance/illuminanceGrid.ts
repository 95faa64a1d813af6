import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { toRadiance, vecText } from './radianceFrame';
import { pointInsideRoom } from '../../core/room/ceilingHeightAt';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';

/** Points of a horizontal plane at `height`, cell centres of a grid of about `spacing` metres, in luxbox's world. */
export function planeGrid(room: { width: number; depth: number }, height: number, spacing: number): Vec3[] {
  const nx = Math.max(1, Math.round(room.width / spacing));
  const nz = Math.max(1, Math.round(room.depth / spacing));
  const points: Vec3[] = [];
  for (let k = 0; k < nz; k++) for (let i = 0; i < nx; i++) points.push([((i + 0.5) / nx) * room.width, height, ((k + 0.5) / nz) * room.depth]);
  return points;
}

/**
 * planeGrid for a room of any shape (lighting scene version 3): the grid over the outline's
 * bounding box, keeping the points inside the outline and under the ceiling (a grid at 0.75 m
 * loses the points under a low slope); a box room's grid is planeGrid's.
 */
export function roomPlaneGrid(room: { width: number; depth: number; shape?: ShapedRoom }, height: number, spacing: number): Vec3[] {
  const shape = room.shape;
  if (!shape) return planeGrid(room, height, spacing);
  const x0 = Math.min(...shape.corners.map((c) => c[0]));
  const z0 = Math.min(...shape.corners.map((c) => c[1]));
  return planeGrid(room, height, spacing)
    .map(([x, y, z]): Vec3 => [x + x0, y, z + z0])
    .filter((p) => pointInsideRoom(shape, p));
}

/**
 * `rtrace -I` input: one line per point, "X Y Z dX dY dZ" in Radiance's frame, the direction
 * being the normal of the plane the illuminance is wanted on (here: up, +Z).
 */
export function rtracePoints(points: readonly Vec3[], normal: Vec3 = [0, 1, 0]): string {
  const n = toRadiance(normal);
  return points.map((p) => `${vecText(toRadiance(p))} ${vecText(n)}`).join('\n') + '\n';
}
