import type { TriangleMesh } from '../../mesh/triangleMesh';
import type { Configuration, RoomObject } from '../configuration/configuration';
import { objectMesh, placedBounds } from './objectGeometry';

/** Lattice of the positions tried (m): fine enough to slide between pieces, coarse enough to try a 10 × 10 m room in milliseconds. */
export const FREE_SPOT_STEP = 0.05;

/** Clearance kept between a new piece and the others (m), so they do not touch on the plan. */
const CLEARANCE = 0.02;

interface Footprint {
  x0: number;
  x1: number;
  z0: number;
  z1: number;
}

/**
 * Where a new floor piece should go (issue #27, "Furniture"): the lattice point nearest `near`
 * where its plan footprint (the axis-aligned bounds of its placed mesh, turned by `yaw`, scaled)
 * lies inside the room and keeps CLEARANCE from every object already on the floor, so a coffee
 * table never lands in the sofa. Null when no such spot exists (the room is full): the caller
 * places it at `near` and the model fits it into the room as before.
 */
export function freeFloorSpot(config: Configuration, mesh: TriangleMesh, near: { x: number; z: number }, yaw = 0, scale = 1): { x: number; z: number } | null {
  const { room } = config;
  const probe: RoomObject = { id: '', source: { kind: 'imported', mesh: '' }, placement: { on: 'floor', x: 0, z: 0 }, yaw, scale, finishes: {} };
  const own = placedBounds(probe, mesh, room);
  const taken: Footprint[] = config.objects
    .filter((o) => o.placement.on === 'floor')
    .map((o) => {
      const b = placedBounds(o, objectMesh(config, o.id), room);
      return { x0: b.min[0] - CLEARANCE, x1: b.max[0] + CLEARANCE, z0: b.min[2] - CLEARANCE, z1: b.max[2] + CLEARANCE };
    });
  const fits = (x: number, z: number): boolean => {
    const f = { x0: x + own.min[0], x1: x + own.max[0], z0: z + own.min[2], z1: z + own.max[2] };
    if (f.x0 < 0 || f.z0 < 0 || f.x1 > room.width || f.z1 > room.depth) return false;
    return taken.every((t) => f.x1 <= t.x0 || f.x0 >= t.x1 || f.z1 <= t.z0 || f.z0 >= t.z1);
  };
  if (fits(near.x, near.z)) return { x: near.x, z: near.z };
  const nx = Math.floor(room.width / FREE_SPOT_STEP);
  const nz = Math.floor(room.depth / FREE_SPOT_STEP);
  const candidates: Array<[number, number, number]> = [];
  for (let i = 0; i <= nx; i++) {
    for (let k = 0; k <= nz; k++) {
      const x = Math.round(i * FREE_SPOT_STEP * 100) / 100;
      const z = Math.round(k * FREE_SPOT_STEP * 100) / 100;
      candidates.push([(x - near.x) ** 2 + (z - near.z) ** 2, x, z]);
    }
  }
  candidates.sort((a, b) => a[0] - b[0] || a[1] - b[1] || a[2] - b[2]);
  for (const [, x, z] of candidates) if (fits(x, z)) return { x, z };
  return null;
}
