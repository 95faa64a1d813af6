import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import type { TileFrame } from './tileFrame';

/** One bright tile as the gather sees it: a uniformly emitting rectangle on a room surface or an atlas chart. */
export interface BrightPatch {
  /** Source index: a room surface 0–5, or ATLAS_SOURCE + chart (tileFrame.ts). */
  surface: number;
  /** Tile indices on that surface. */
  tileU: number;
  tileV: number;
  /** Centre (world), half edges along the surface's u and v axes (metres). */
  centre: Vec3;
  halfU: number;
  halfV: number;
  /** Unit directions of the half edges (v's already times the frame's vSign). */
  axisU: Vec3;
  axisV: Vec3;
  /** Reflected flux ρ·Φ per channel, lm, and the exitance M = flux / area of the rectangle. */
  flux: Rgb;
  exitance: Rgb;
}

/** Per-tile sums of one surface or chart, as the tile pass writes them (4 floats per tile in each array). */
export interface SurfaceTileSums {
  /** What was tiled; its reflectance multiplies the sums (1 for a chart, whose sums carry ρ). */
  frame: TileFrame;
  /** Texels per tile edge. */
  tile: number;
  tilesU: number;
  tilesV: number;
  /** (Σ E_r·a, Σ E_g·a, Σ E_b·a, Σ y²·a) per tile, y = Y(ρ·E). */
  sums: Float32Array;
  /** (Σ y·a·u, Σ y·a·v, Σ y·a·u², Σ y·a·v²), u, v from the tile corner, metres. */
  moments: Float32Array;
}

export interface BrightSelection {
  patches: BrightPatch[];
  /** Peakedness S·Σ M²A / (Σ M A)² of all exitance (1 = uniform), and the same with Σ M²A over only what the Monte Carlo gather still samples. */
  peakedness: number;
  residualPeakedness: number;
}

/** A tile bright enough to qualify: its Σ y²·a score, reflected flux ρ·Φ per channel and Y of it. */
interface Candidate {
  s: SurfaceTileSums;
  k: number;
  score: number;
  flux: Rgb;
  y: number;
}

/** Y of tile `k`'s reflected flux, lm (negative sums clamped: float noise of an unlit tile). */
function yOfTile(s: SurfaceTileSums, k: number): number {
  return (
    LUMINANCE_WEIGHTS[0] * Math.max(0, s.sums[4 * k]) * s.frame.reflectance[0] + LUMINANCE_WEIGHTS[1] * Math.max(0, s.sums[4 * k + 1]) * s.frame.reflectance[1] + LUMINANCE_WEIGHTS[2] * Math.max(0, s.sums[4 * k + 2]) * s.frame.reflectance[2]
  );
}

/** The area of all surfaces, Σ score and Σ y over all lit tiles (no allocation per tile: a 20 m corridor has ~25 000 tiles). */
function roomTotals(surfaces: SurfaceTileSums[]): { area: number; scoreAll: number; yAll: number } {
  let area = 0;
  let scoreAll = 0;
  let yAll = 0;
  for (const s of surfaces) {
    area += s.frame.area;
    for (let k = 0; k < s.tilesU * s.tilesV; k++) {
      const y = yOfTile(s, k);
      const score = Math.max(0, s.sums[4 * k + 3]);
      if (!(y > 0) || !Number.isFinite(y) || !Number.isFinite(score)) continue;
      scoreAll += score;
      yAll += y;
    }
  }
  return { area, scoreAll, yAll };
}

/** The tiles whose mean exitance is at least `minContrast` × the room mean, unsorted. */
function candidatesOf(surfaces: SurfaceTileSums[], minContrast: number, meanExitance: number): Candidate[] {
  const candidates: Candidate[] = [];
  for (const s of surfaces) {
    const du = s.frame.lengthU / s.frame.width;
    const dv = s.frame.lengthV / s.frame.height;
    for (let k = 0; k < s.tilesU * s.tilesV; k++) {
      const y = yOfTile(s, k);
      const score = Math.max(0, s.sums[4 * k + 3]);
      // The tile's own area (the last row and column may be partial).
      const iu = k % s.tilesU;
      const iv = Math.floor(k / s.tilesU);
      const tileArea = (Math.min(s.frame.width, (iu + 1) * s.tile) - iu * s.tile) * du * (Math.min(s.frame.height, (iv + 1) * s.tile) - iv * s.tile) * dv;
      if (!(y >= minContrast * meanExitance * tileArea) || !Number.isFinite(y) || !Number.isFinite(score)) continue;
      const flux = [0, 1, 2].map((c) => Math.max(0, s.sums[4 * k + c]) * s.frame.reflectance[c]) as Rgb;
      candidates.push({ s, k, score, flux, y });
    }
  }
  return candidates;
}

/** The candidate as a moment-matched rectangle, or null where its mean exitance over the tile's clipped extent is under the contrast. */
function patchOf(c: Candidate, minContrast: number, meanExitance: number): BrightPatch | null {
  const { frame: layout, tile } = c.s;
  const du = layout.lengthU / layout.width;
  const dv = layout.lengthV / layout.height;
  const iu = c.k % c.s.tilesU;
  const iv = Math.floor(c.k / c.s.tilesU);
  // Tile extent (the last row/column may be partial).
  const u0 = iu * tile * du;
  const v0 = iv * tile * dv;
  const u1 = Math.min(layout.lengthU, (iu + 1) * tile * du);
  const v1 = Math.min(layout.lengthV, (iv + 1) * tile * dv);
  if (c.y / ((u1 - u0) * (v1 - v0)) < minContrast * meanExitance) return null;
  const m = c.s.moments.subarray(4 * c.k, 4 * c.k + 4);
  // Flux centroid and spread of the tile's exitance (plus the spread inside a texel).
  const mu = m[0] / c.y;
  const mv = m[1] / c.y;
  const varU = Math.max(0, m[2] / c.y - mu * mu) + (du * du) / 12;
  const varV = Math.max(0, m[3] / c.y - mv * mv) + (dv * dv) / 12;
  const cu = u0 + Math.min(Math.max(mu, 0), u1 - u0);
  const cv = v0 + Math.min(Math.max(mv, 0), v1 - v0);
  // A uniform rectangle with the same mean and variance has half edge √3·σ; keep it in the tile.
  const halfU = Math.max(1e-4, Math.min(Math.sqrt(3 * varU), cu - u0, u1 - cu));
  const halfV = Math.max(1e-4, Math.min(Math.sqrt(3 * varV), cv - v0, v1 - cv));
  // On a room surface of the box origin is 0 along u and v and the axes are unit axes: cu, cv to the bit.
  const centre = [0, 1, 2].map((a) => layout.origin[a] + cu * layout.axisU[a] + cv * layout.axisV[a]) as Vec3;
  const rectArea = 4 * halfU * halfV;
  return {
    surface: layout.index,
    tileU: iu,
    tileV: iv,
    centre,
    halfU,
    halfV,
    axisU: layout.axisU,
    axisV: layout.axisV.map((x) => x * layout.vSign) as Vec3,
    flux: c.flux,
    exitance: c.flux.map((f) => f / rectArea) as Rgb,
  };
}

/**
 * Which tiles to gather deterministically. The variance of the cosine-sampled
 * gather of bounce 1 is, up to geometry, Σ M²·A over what it samples; for a
 * uniform exitance of the same flux it would be (Σ M·A)²/S. Tiles are taken in
 * decreasing Σ M²·A until the "peakedness" S·Σ M²A/(Σ MA)² of what the gather
 * still samples (Σ M²A over the residual, Σ MA over all exitance) is below
 * `targetPeakedness`, at most `maxPatches`, and only tiles whose mean exitance is
 * above `minContrast` × the room mean (a smooth room selects nothing and pays
 * nothing).
 */
export function selectBrightPatches(surfaces: SurfaceTileSums[], options: { maxPatches: number; targetPeakedness: number; minContrast: number }): BrightSelection {
  // Totals first, then only the tiles bright enough to qualify become candidates and are sorted.
  const { area, scoreAll, yAll } = roomTotals(surfaces);
  const meanExitance = yAll / area;
  const candidates = candidatesOf(surfaces, options.minContrast, meanExitance);
  // Relative to all of the exitance: the residual's noise against the whole signal.
  const peak = (score: number) => (yAll > 0 ? (area * score) / (yAll * yAll) : 1);
  const peakedness = peak(scoreAll);
  const patches: BrightPatch[] = [];
  if (!(yAll > 0) || options.maxPatches <= 0) return { patches, peakedness, residualPeakedness: peakedness };
  candidates.sort((a, b) => b.score - a.score);
  let score = scoreAll;
  for (const c of candidates) {
    if (patches.length >= options.maxPatches || peak(score) <= options.targetPeakedness) break;
    const patch = patchOf(c, options.minContrast, meanExitance);
    if (!patch) continue;
    patches.push(patch);
    score -= c.score;
  }
  return { patches, peakedness, residualPeakedness: peak(Math.max(0, score)) };
}
