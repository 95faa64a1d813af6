import type { ObjectPlacement, Room, WallName } from '../../core/model/configuration/configuration';
import type { PlanPoint } from './viewTransform';

/** The direction of a wall's u axis in the plan (docs/scene-format.md: north/south u = x, west/east u = z). */
export function wallAxis(wall: WallName): PlanPoint {
  return wall === 'north' || wall === 'south' ? { x: 1, z: 0 } : { x: 0, z: 1 };
}

/**
 * The part of a plan movement an object can follow: all of it on the floor, only the part along
 * its wall for a wall item (a picture slides along its wall; it is never dragged off it).
 */
export function followableDelta(placement: ObjectPlacement, delta: PlanPoint): PlanPoint {
  if (placement.on === 'floor') return delta;
  const a = wallAxis(placement.wall);
  return { x: a.x * delta.x, z: a.z * delta.z };
}

/**
 * The placement after moving by `delta` (metres in the plan), rounded to `snap` metres (the drag
 * snaps to whole centimetres so fields show clean numbers; arrow keys round to the millimetre so
 * repeated steps gather no float noise).
 */
export function movedPlacement(placement: ObjectPlacement, delta: PlanPoint, snap: number): ObjectPlacement {
  // Dividing by a whole number of steps per metre keeps 1.23 exactly 1.23 (× 0.01 would not).
  const perMetre = Math.round(1 / snap);
  const round = (v: number) => Math.round(v * perMetre) / perMetre;
  if (placement.on === 'floor') return { on: 'floor', x: delta.x ? round(placement.x + delta.x) : placement.x, z: delta.z ? round(placement.z + delta.z) : placement.z };
  const along = placement.wall === 'north' || placement.wall === 'south' ? delta.x : delta.z;
  return { ...placement, u: along ? round(placement.u + along) : placement.u };
}

/**
 * A wall placement on the wall nearest to a plan point, at that point's position along it and
 * height `y` (docs/scene-format.md: north z = 0, south z = D, west x = 0, east x = W).
 */
export function wallPlacementNear(room: Pick<Room, 'width' | 'depth'>, p: PlanPoint, y: number): ObjectPlacement {
  const distances: [WallName, number][] = [
    ['north', p.z],
    ['south', room.depth - p.z],
    ['west', p.x],
    ['east', room.width - p.x],
  ];
  const [wall] = distances.reduce((a, b) => (b[1] < a[1] ? b : a));
  return { on: 'wall', wall, u: wall === 'north' || wall === 'south' ? p.x : p.z, y };
}
