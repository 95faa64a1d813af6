/**
 * Illuminance statistics of a shaped room's surfaces (issue 29): they are the first objects of the
 * atlas (engines/bake/shapedRoom), so each surface's numbers come from its atlas texels, each
 * weighing its coverage (the exact share of the texel the surface covers; a texel inside an
 * opening covers nothing and does not count).
 */
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import type { ObjectAtlas, PreparedObjects } from '../bake/objects/preparedObjects';
import { ROOM_OBJECT_PREFIX } from '../bake/shapedRoom/roomSurfaceObjects';
import type { IlluminanceStats } from './lightStats';

export interface RoomSurfaceStats extends IlluminanceStats {
  /** 'floor', 'ceiling', 'slope-<i>', 'wall-<i>' (src/core/room/roomSurfaces.ts). */
  surface: string;
  /** m², openings left out (Σ coverage · texel²). */
  area: number;
}

/** Per surface of the shaped room: coverage-weighted mean, lowest and highest texel (lux, Y) of `total` (RGB per atlas texel), U0 = min/mean. Empty for a box room. */
export function roomSurfaceStats(prepared: PreparedObjects, total: Float32Array, atlas: ObjectAtlas = prepared.atlas): RoomSurfaceStats[] {
  const surfaces: string[] = [];
  for (const o of prepared.objects) {
    if (!o.id.startsWith(ROOM_OBJECT_PREFIX)) break;
    surfaces.push(o.id.slice(ROOM_OBJECT_PREFIX.length));
  }
  const sums = surfaces.map(() => ({ e: 0, w: 0, min: Infinity, max: -Infinity, n: 0 }));
  for (let t = 0; t < atlas.width * atlas.height; t++) {
    const w = atlas.position[4 * t + 3];
    if (!(w > 0)) continue;
    const s = sums[atlas.reflectance[4 * t + 3] - 1];
    if (!s) continue;
    const y = LUMINANCE_WEIGHTS[0] * total[3 * t] + LUMINANCE_WEIGHTS[1] * total[3 * t + 1] + LUMINANCE_WEIGHTS[2] * total[3 * t + 2];
    s.e += y * w;
    s.w += w;
    s.n++;
    s.min = Math.min(s.min, y);
    s.max = Math.max(s.max, y);
  }
  const s2 = atlas.texelSize * atlas.texelSize;
  return surfaces.map((surface, k) => {
    const s = sums[k];
    const avg = s.w > 0 ? s.e / s.w : 0;
    return { surface, area: s.w * s2, avg, min: s.n ? s.min : 0, max: s.n ? s.max : 0, u0: avg > 0 ? (s.n ? s.min : 0) / avg : 0, points: s.n };
  });
}
