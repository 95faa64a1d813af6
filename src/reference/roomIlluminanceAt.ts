import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import { frontFormFactor } from './occludedFormFactor';
import { roomDirectAt } from './roomDirect';
import { sightClear } from './roomSightlines';
import { luminanceOf, PieceCache, pointToPatch, type RoomReferenceResult } from './solveRoomReference';

export interface RoomSample {
  direct: number;
  indirect: number;
  total: number;
  directRgb: Rgb;
  indirectRgb: Rgb;
}

const caches = new WeakMap<RoomReferenceResult, PieceCache>();

/**
 * Illuminance (lux) at point p with unit normal n in a solved room: the exact direct light with
 * the room's own shadows, plus the final gather Σ_j F_vis(p → patch j)·M_j over all patches. A
 * patch within two of its diameters is taken in 16 pieces, each with its own sight line and
 * exitance ρ·(exact direct light at the piece's centroid + the patch's E_ind), so corners and
 * hot spots next to p are resolved. `directAt` gives the direct light at a point (default: the
 * luminaires' point sources with the room's shadows; daylight passes its own).
 */
export function roomIlluminanceAt(r: RoomReferenceResult, p: Vec3, n: Vec3, directAt: (q: Vec3, m: Vec3, out: Rgb) => Rgb = (q, m, out) => roomDirectAt(r.sources, r.sight, q, m, out)): RoomSample {
  let cache = caches.get(r);
  if (!cache) caches.set(r, (cache = new PieceCache(r.patches)));
  const directRgb = directAt(p, n, [0, 0, 0]);
  const indirectRgb: Rgb = [0, 0, 0];
  const e: Rgb = [0, 0, 0];
  r.patches.forEach((patch, j) => {
    const k = 3 * j;
    if (!(r.exitanceRgb[k] > 0 || r.exitanceRgb[k + 1] > 0 || r.exitanceRgb[k + 2] > 0)) return;
    const near = Math.hypot(p[0] - patch.centroid[0], p[1] - patch.centroid[1], p[2] - patch.centroid[2]) < 2 * patch.diameter;
    if (!near) {
      const f = pointToPatch(r.sight, p, n, patch, j, cache);
      for (let c = 0; c < 3; c++) indirectRgb[c] += f * r.exitanceRgb[k + c];
      return;
    }
    const v0 = patch.vertices[0];
    if (patch.normal[0] * (p[0] - v0[0]) + patch.normal[1] * (p[1] - v0[1]) + patch.normal[2] * (p[2] - v0[2]) <= 1e-12) return;
    for (const piece of cache.get(j, 2)) {
      if (!sightClear(r.sight, p, n, piece.centroid, patch.normal)) continue;
      const f = frontFormFactor(p, n, piece.vertices);
      if (!(f > 0)) continue;
      directAt(piece.centroid, patch.normal, e);
      for (let c = 0; c < 3; c++) indirectRgb[c] += f * patch.reflectance[c] * (e[c] + r.indirectRgb[k + c]);
    }
  });
  return {
    direct: luminanceOf(directRgb, 0),
    indirect: luminanceOf(indirectRgb, 0),
    total: luminanceOf(directRgb, 0) + luminanceOf(indirectRgb, 0),
    directRgb,
    indirectRgb,
  };
}

/**
 * Illuminance at a point of a named surface ('floor', 'ceiling', 'slope-<i>', 'wall-<i>', as
 * src/core/room/roomSurfaces.ts names them), with that surface's inward normal: what a baker
 * texel centre on that surface is compared with.
 */
export function roomSurfaceIlluminanceAt(r: RoomReferenceResult, surfaceId: string, p: Vec3): RoomSample {
  const surface = r.surfaces.find((s) => s.id === surfaceId);
  if (!surface) throw new RangeError(`no surface '${surfaceId}' in this room (it has ${r.surfaces.map((s) => s.id).join(', ')})`);
  return roomIlluminanceAt(r, p, [...surface.inward]);
}

export interface RoomSurfaceStatistics {
  id: string;
  /** m², openings excluded. */
  area: number;
  /** Area-weighted mean, lowest and highest patch mean, lux (Y). */
  mean: number;
  min: number;
  max: number;
  /** Σ E·A over the surface, lm. */
  flux: number;
}

/** Per surface: area, mean, lowest and highest patch illuminance (total, Y), flux received. */
export function roomSurfaceStatistics(r: RoomReferenceResult): RoomSurfaceStatistics[] {
  return r.surfaces.map((s, k) => {
    let flux = 0;
    let area = 0;
    let min = Infinity;
    let max = -Infinity;
    r.patches.forEach((p, i) => {
      if (p.surface !== k || p.kind === 'opening') return;
      const e = luminanceOf(r.directRgb, 3 * i) + luminanceOf(r.indirectRgb, 3 * i);
      flux += e * p.area;
      area += p.area;
      min = Math.min(min, e);
      max = Math.max(max, e);
    });
    return { id: s.id, area, mean: area > 0 ? flux / area : 0, min, max, flux };
  });
}
