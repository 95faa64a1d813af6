import type { Vec3 } from '../model/lightingScene';
import type { Photometry } from '../photometry/types';

/**
 * Point sources that stand in for a luminous opening, in the luminaire frame
 * (width along local x, length along local z, as in Photometry.luminousOpening).
 * Each carries 1/n of the measured intensity distribution. A far-field
 * photometry is only valid at distances of ~5× the opening (the "five-times
 * rule", IES LM-63 / CIE 121); splitting the opening into cells no larger than
 * `spacing` moves that limit close to the lamp, which is what commercial
 * calculation programs do (and the seed paper, §3.1). Openings smaller than
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
      if (round && w > 0 && l > 0 && (2 * x / w) ** 2 + (2 * z / l) ** 2 > 1) continue;
      points.push([x, 0, z]);
    }
  }
  return points.length > 0 ? points : [[0, 0, 0]];
}
