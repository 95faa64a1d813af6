/**
 * A shaped room's bake (issue 29) against the independent room reference
 * (src/reference/solveRoomReference.ts), at the G-buffer point of fully covered atlas texels of the
 * room's surfaces; points within EDGE_BAND of an edge of their surface or of an opening are left
 * out and counted (the rule). Used by `luxbox bench` (shapedRoomBench.ts) and the tests.
 */
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { roomSurfaces, type RoomSurface } from '../../core/room/roomSurfaces';
import type { PlanPoint } from '../../core/room/planPolygon';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../engines/bake/bakedMaps';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';
import { roomSurfaceIlluminanceAt } from '../../reference/roomIlluminanceAt';
import type { RoomReferenceResult } from '../../reference/solveRoomReference';

export interface SurfacePoint {
  surface: string;
  /** World point and the bake's and the reference's values there (lux, Y). */
  point: Vec3;
  bake: { direct: number; total: number };
  reference: { direct: number; total: number };
}

export interface ShapedComparison {
  points: SurfacePoint[];
  /** Fully covered texels left out because their point lies within EDGE_BAND of a surface's edge or an opening's. */
  nearEdge: number;
}

/** Points this close (m) to an edge of their surface or of an opening are left out of the accuracy figures (issue 29). */
export const EDGE_BAND = 0.05;

function distanceToSegment(p: PlanPoint, a: PlanPoint, b: PlanPoint): number {
  const [dx, dz] = [b[0] - a[0], b[1] - a[1]];
  const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / (dx * dx + dz * dz)));
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dz);
}

/** Distance (m) from a point of the surface to the nearest edge of its polygons or of an opening in it. */
export function distanceToEdges(s: RoomSurface, p: Vec3): number {
  const d = [p[0] - s.frame.origin[0], p[1] - s.frame.origin[1], p[2] - s.frame.origin[2]];
  const q: PlanPoint = [d[0] * s.frame.u[0] + d[1] * s.frame.u[1] + d[2] * s.frame.u[2], d[0] * s.frame.v[0] + d[1] * s.frame.v[1] + d[2] * s.frame.v[2]];
  let best = Infinity;
  for (const poly of [...s.polygons2d, ...s.openings.map((o) => o.polygon2d)]) {
    for (let i = 0; i < poly.length; i++) best = Math.min(best, distanceToSegment(q, poly[i], poly[(i + 1) % poly.length]));
  }
  return best;
}

/** Light at a point of a room surface, as a reference gives it. */
export type ReferenceAt = (surface: RoomSurface, point: Vec3) => { direct: number; total: number };

/**
 * Every `stride`-th fully covered atlas texel of a shaped room's surfaces: the bake's direct and
 * total against `referenceAt` at the texel's G-buffer point, points within EDGE_BAND of an edge
 * left out and counted. The electric and the daylight comparisons differ only in the reference.
 */
export function compareAtlasWith(scene: BakeScene, maps: BakedMaps, stride: number, referenceAt: ReferenceAt): ShapedComparison {
  const enclosure = encloseShapedRoom(scene).room.enclosure;
  const o = maps.objects;
  if (!enclosure || !o) throw new Error('not a shaped room bake');
  const surfaces = new Map(roomSurfaces(enclosure.shape).map((s) => [s.id, s]));
  const [direct, total] = [luxOf(o.direct), luxOf(o.total)];
  const { position, reflectance } = o.atlas;
  const out: ShapedComparison = { points: [], nearEdge: 0 };
  let covered = 0;
  for (let k = 0; k < o.atlas.width * o.atlas.height; k++) {
    if (position[4 * k + 3] < 0.999) continue;
    const object = reflectance[4 * k + 3] - 1;
    if (object >= enclosure.surfaces.length) continue;
    if (covered++ % stride !== 0) continue;
    const surface = surfaces.get(enclosure.surfaces[object])!;
    const p: Vec3 = [position[4 * k] - enclosure.offset[0], position[4 * k + 1] - enclosure.offset[1], position[4 * k + 2] - enclosure.offset[2]];
    if (distanceToEdges(surface, p) < EDGE_BAND) {
      out.nearEdge++;
      continue;
    }
    const r = referenceAt(surface, p);
    out.points.push({ surface: surface.id, point: p, bake: { direct: direct[k], total: total[k] }, reference: { direct: r.direct, total: r.total } });
  }
  return out;
}

/** Every `stride`-th fully covered atlas texel of the room's surfaces: the bake's direct and total against the room reference's at the texel's point. */
export function compareWithReference(scene: BakeScene, maps: BakedMaps, reference: RoomReferenceResult, stride: number): ShapedComparison {
  return compareAtlasWith(scene, maps, stride, (surface, p) => roomSurfaceIlluminanceAt(reference, surface.id, p));
}

/** RMS and largest relative error of `kind` over the points whose reference exceeds `floor` lux. */
export function relativeErrors(points: readonly SurfacePoint[], kind: 'direct' | 'total', floor: number): { n: number; rms: number; max: number; worst: SurfacePoint | null } {
  let sum = 0;
  let max = 0;
  let worst: SurfacePoint | null = null;
  let n = 0;
  for (const p of points) {
    if (!(p.reference[kind] > floor)) continue;
    const e = Math.abs(p.bake[kind] / p.reference[kind] - 1);
    n++;
    sum += e * e;
    if (e > max) [max, worst] = [e, p];
  }
  return { n, rms: n ? Math.sqrt(sum / n) : 0, max, worst };
}
