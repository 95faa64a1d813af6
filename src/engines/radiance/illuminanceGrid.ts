import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { toRadiance, vecText } from './radianceFrame';

/** Points of a horizontal plane at `height`, cell centres of a grid of about `spacing` metres, in luxbox's world. */
export function planeGrid(room: { width: number; depth: number }, height: number, spacing: number): Vec3[] {
  const nx = Math.max(1, Math.round(room.width / spacing));
  const nz = Math.max(1, Math.round(room.depth / spacing));
  const points: Vec3[] = [];
  for (let k = 0; k < nz; k++) for (let i = 0; i < nx; i++) points.push([((i + 0.5) / nx) * room.width, height, ((k + 0.5) / nz) * room.depth]);
  return points;
}

/**
 * `rtrace -I` input: one line per point, "X Y Z dX dY dZ" in Radiance's frame, the direction
 * being the normal of the plane the illuminance is wanted on (here: up, +Z).
 */
export function rtracePoints(points: readonly Vec3[], normal: Vec3 = [0, 1, 0]): string {
  const n = toRadiance(normal);
  return points.map((p) => `${vecText(toRadiance(p))} ${vecText(n)}`).join('\n') + '\n';
}
