import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import { occludedDirectAt } from './occludedDirect';
import { occludedFormFactor, polygonCentroid, splitPolygon } from './occludedFormFactor';
import { ReferenceInputError } from './referenceInputError';
import { LUMINANCE_WEIGHTS } from './solveBoxReference';
import type { FurnishedResult } from './solveFurnishedReference';

export interface FurnishedSample {
  /** Lux, luminance-weighted (Y). */
  direct: number;
  indirect: number;
  total: number;
  directRgb: Rgb;
  indirectRgb: Rgb;
  totalRgb: Rgb;
}

const y = (c: Rgb): number => LUMINANCE_WEIGHTS[0] * c[0] + LUMINANCE_WEIGHTS[1] * c[1] + LUMINANCE_WEIGHTS[2] * c[2];

/** Emitters nearer than this many of their diameters are gathered in 16 pieces with finer visibility. */
const NEAR_DIAMETERS = 2;

/**
 * Illuminance at any point with any unit normal in a solved furnished room — a wall
 * texel centre, an object atlas texel (point and normal from the baker's G-buffer).
 * Direct light is exact at the point, with a shadow ray per source. Indirect light is
 * a final gather over every patch, E_ind(p) = Σ_j F_vis(dA_p → j) · M_j, with the
 * converged exitances M_j and visibility refined to 1/16 of the patch. A patch within two
 * of its diameters is split 16 ways instead, each piece with visibility refined to 1/256
 * of the patch and exitance ρ·(E_dir at the piece's centre, exact and shadowed, + the
 * patch's E_ind): direct light varies fastest, so it is resolved where it is seen closest.
 */
export function furnishedIlluminanceAt(result: FurnishedResult, point: Vec3, normal: Vec3): FurnishedSample {
  if (point.length !== 3 || !point.every(Number.isFinite)) throw new ReferenceInputError(`sample point [${point.join(', ')}]: expected three finite numbers`);
  const len = Math.hypot(normal[0], normal[1], normal[2]);
  if (!(len > 0) || !Number.isFinite(len)) throw new ReferenceInputError(`sample normal [${normal.join(', ')}]: expected a finite non-zero vector`);
  const n: Vec3 = [normal[0] / len, normal[1] / len, normal[2] / len];
  const { extent } = result;
  // A hair inside the room: a point exactly on an edge of the box is a singular point of the
  // contour integral. A nanometre-scale inset changes the direct light by ~1e-9 relative.
  const inset = 1e-9 * Math.max(...extent);
  const p = point.map((c, a) => Math.min(Math.max(c, inset), extent[a] - inset)) as Vec3;
  if (point.some((c, a) => Math.abs(c - p[a]) > 0.01)) {
    throw new ReferenceInputError(`sample point [${point.join(', ')}]: outside the ${extent.join(' × ')} m room`);
  }
  const directRgb = occludedDirectAt(result.sources, result.occluders, p, n);
  const indirectRgb: Rgb = [0, 0, 0];
  const fine = { minDepth: 0, maxDepth: 2 };
  const far = { minDepth: 0, maxDepth: 2 };
  const m = result.exitanceRgb;
  const e: Rgb = [0, 0, 0];
  result.patches.forEach((q, j) => {
    const rho = q.reflectance;
    if (rho[0] === 0 && rho[1] === 0 && rho[2] === 0) return;
    const gap = Math.hypot(q.centroid[0] - p[0], q.centroid[1] - p[1], q.centroid[2] - p[2]);
    if (gap >= NEAR_DIAMETERS * q.diameter) {
      const f = occludedFormFactor(p, n, q.vertices, q.normal, result.occluders, far);
      if (f > 0) for (let c = 0; c < 3; c++) indirectRgb[c] += f * m[3 * j + c];
      return;
    }
    // A near patch: 16 pieces, each with its own exact direct light (shadow edges and hot
    // spots inside the patch, the wall behind a cabinet) plus the patch's indirect light.
    let pieces: Vec3[][] = [q.vertices];
    for (let level = 0; level < 2; level++) pieces = pieces.flatMap((v) => splitPolygon(v));
    for (const piece of pieces) {
      const f = occludedFormFactor(p, n, piece, q.normal, result.occluders, fine);
      if (f === 0) continue;
      occludedDirectAt(result.sources, result.occluders, polygonCentroid(piece), q.normal, e);
      for (let c = 0; c < 3; c++) indirectRgb[c] += f * rho[c] * (e[c] + result.indirectRgb[3 * j + c]);
    }
  });
  const totalRgb: Rgb = [directRgb[0] + indirectRgb[0], directRgb[1] + indirectRgb[1], directRgb[2] + indirectRgb[2]];
  return { direct: y(directRgb), indirect: y(indirectRgb), total: y(totalRgb), directRgb, indirectRgb, totalRgb };
}
