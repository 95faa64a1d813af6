import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';

/**
 * Point sources that stand in for a luminous opening, in the luminaire frame
 * (width along local x, length along local z, as in Photometry.luminousOpening).
 * Each carries 1/n of the measured intensity distribution. A far-field
 * photometry is only valid at distances of ~5× the opening (the "five-times
 * rule", IES LM-63 / CIE 121); splitting the opening into cells no larger than
 * `spacing` moves that limit close to the lamp, which is what commercial
 * calculation programs do (and the configurator paper, §3.1). Openings smaller than
 * `spacing` stay one point. Circular/elliptical openings keep the cells whose
 * centres fall inside the ellipse.
 */
export function pointSources(photometry: Photometry, spacing: number, maxPerAxis: number): Vec3[] {
  const { width, length, shape } = photometry.luminousOpening;
  const w = Math.abs(width);
  const l = Math.abs(length);
  if (!(spacing > 0) || (w <= spacing && l <= spacing)) return [[0, 0, 0]];
  const nx = Math.max(1, Math.min(maxPerAxis, Math.ceil(w / spacing)));
  const nz = Math.max(1, Math.min(maxPerAxis, Math.ceil(l / spacing)));
  const round = shape === 'circular' || shape === 'elliptical' || shape === 'spherical' || shape === 'cylindrical';
  const points: Vec3[] = [];
  for (let i = 0; i < nx; i++) {
    for (let k = 0; k < nz; k++) {
      const x = ((i + 0.5) / nx - 0.5) * w;
      const z = ((k + 0.5) / nz - 0.5) * l;
      if (round && w > 0 && l > 0 && ((2 * x) / w) ** 2 + ((2 * z) / l) ** 2 > 1) continue;
      points.push([x, 0, z]);
    }
  }
  return points.length > 0 ? points : [[0, 0, 0]];
}

/** The faces of a tall opening stay at least this far inside the room (metres). */
export const FACE_MARGIN = 0.01;

/** A point source of a luminous opening, in the luminaire frame, and the half of the sphere it emits into. */
export interface OpeningSource {
  position: Vec3;
  /**
   * −1: only directions with local y < 0 (the downward hemisphere, from the bottom face);
   * +1: only local y > 0 (upward, from the top face); 0: all directions.
   */
  side: -1 | 0 | 1;
}

/**
 * The point sources of a luminous opening with its vertical extent
 * (docs/baker.md, "Luminous openings"). An opening taller than `spacing`
 * (a cylinder or box that emits from its sides and top, e.g. a 13 cm ceiling
 * luminaire with an up-light part) gets its grid twice: at the bottom face
 * (local y = −h/2) for the downward hemisphere and at the top face (y = +h/2)
 * for the upward one; each direction is emitted by exactly one grid, so the
 * flux and the far field are unchanged and the weight per source is 1 / (grid
 * size). A flat opening (or one no taller than `spacing`) keeps one grid in
 * the plane through the photometric centre. `room` (the luminaire's room
 * distances along its local −y and +y) keeps each face at least FACE_MARGIN
 * inside the room: a luminaire mounted closer to the ceiling than half its
 * height has its top face between its centre and the ceiling, not on or
 * beyond it (where its up-light would leave the room and be lost).
 */
export function openingSources(photometry: Photometry, spacing: number, maxPerAxis: number, room: { down: number; up: number } = { down: Infinity, up: Infinity }): { sources: OpeningSource[]; perGrid: number } {
  const grid = pointSources(photometry, spacing, maxPerAxis);
  const h = Math.abs(photometry.luminousOpening.height);
  if (!(spacing > 0) || !(h > spacing)) return { sources: grid.map((position) => ({ position, side: 0 })), perGrid: grid.length };
  const down = Math.min(h / 2, Math.max(0, room.down - FACE_MARGIN));
  const up = Math.min(h / 2, Math.max(0, room.up - FACE_MARGIN));
  return {
    sources: [...grid.map((p): OpeningSource => ({ position: [p[0], -down, p[2]], side: -1 })), ...grid.map((p): OpeningSource => ({ position: [p[0], up, p[2]], side: 1 }))],
    perGrid: grid.length,
  };
}
