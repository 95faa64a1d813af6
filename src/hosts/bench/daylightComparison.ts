/**
 * A daylight bake (issue 30) against the independent daylight reference
 * (src/reference/solveDaylightReference.ts) at the G-buffer point of fully covered atlas texels of
 * the room's surfaces, with the shaped rooms' rule: points within EDGE_BAND of a surface's or an
 * opening's edge are left out and counted. Used by the tests and `npm run bench`.
 */
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { roomSurfaces } from '../../core/room/roomSurfaces';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { luxOf, type BakedMaps } from '../../engines/bake/bakedMaps';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';
import { daylightIlluminanceAt, type DaylightReferenceResult } from '../../reference/solveDaylightReference';
import { distanceToEdges, EDGE_BAND, type ShapedComparison } from './shapedRoomComparison';

/** Every `stride`-th fully covered texel of the room's surfaces: the bake's direct and total daylight against the reference's at the texel's point. */
export function compareDaylightWithReference(scene: BakeScene, maps: BakedMaps, reference: DaylightReferenceResult, stride: number): ShapedComparison {
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
    const r = daylightIlluminanceAt(reference, p, [surface.inward[0], surface.inward[1], surface.inward[2]]);
    out.points.push({ surface: surface.id, point: p, bake: { direct: direct[k], total: total[k] }, reference: { direct: r.direct, total: r.total } });
  }
  return out;
}
