import { VERTICAL_PAD_DEG } from '../../core/photometry/expandTypeC';
import { intensity } from '../../core/photometry/intensity';
import type { Photometry } from '../../core/photometry/types';

/** One uniform axis of a dense grid: samples at first + i·step, i = 0..count−1. */
export interface DenseAxis {
  first: number;
  step: number;
  count: number;
}

/**
 * How a C angle in [0, 360) is folded onto the stored range before the lookup
 * (the photometry's own symmetry, LM-63-2002 §4.21 / EULUMDAT Isym):
 * - `none`: 0..360 stored;
 * - `bilateral-c0`: I(C) = I(360 − C), 0..180 stored;
 * - `bilateral-c90`: I(C) = I(180 − C), 90..270 stored;
 * - `quadrant`: both, 0..90 stored.
 */
export type CFold = 'none' | 'bilateral-c0' | 'bilateral-c90' | 'quadrant';

/**
 * A photometry resampled once onto a uniform (γ, C) grid, so the shader finds
 * its cell arithmetically (no bin table, no search) and interpolates four
 * values (two for a rotational profile). values[h·gamma.count + g].
 */
export interface DenseProfileGrid {
  gamma: DenseAxis;
  /** null: rotationally symmetric, one row. */
  c: DenseAxis | null;
  fold: CFold;
  values: Float32Array;
  /** True when every measured grid angle lies on the dense grid: bilinear lookup is then the file's own bilinear interpolation (up to float32). */
  aligned: boolean;
}

/** Largest number of γ samples, and of C samples, per profile. */
export const MAX_DENSE_GAMMA = 2049;
export const MAX_DENSE_C = 1441;
/** Largest number of values per profile (4 MiB of R32F): with several profiles the data texture stays within 2048 rows of 2048 for ~4 profiles at the cap. */
export const MAX_DENSE_VALUES = 1 << 20;

/** Relative tolerance with which a grid angle counts as lying on a dense sample. */
const ON_GRID = 1e-6;

/**
 * Largest uniform step over [knots[0], knots[last]] that puts every knot on a
 * sample, with at most maxCount samples; else the finest step allowed
 * (not aligned). Bilinear interpolation of a piecewise-bilinear function on a
 * grid that contains all its kinks reproduces it exactly: on each sub-cell the
 * function is bilinear and fixed by its four corners.
 */
export function alignedAxis(knots: readonly number[], maxCount: number): { axis: DenseAxis; aligned: boolean } {
  const first = knots[0];
  const span = knots[knots.length - 1] - first;
  if (knots.length < 2 || span <= 0) return { axis: { first, step: 1, count: 2 }, aligned: true };
  for (let n = knots.length - 1; n < maxCount; n++) {
    const step = span / n;
    if (knots.every((k) => Math.abs((k - first) / step - Math.round((k - first) / step)) <= ON_GRID * n)) return { axis: { first, step, count: n + 1 }, aligned: true };
  }
  return { axis: { first, step: span / (maxCount - 1), count: maxCount }, aligned: false };
}

function foldOf(ph: Photometry): CFold {
  return ph.symmetry === 'quadrant' || ph.symmetry === 'bilateral-c0' || ph.symmetry === 'bilateral-c90' ? ph.symmetry : 'none';
}

/** The stored C range of a fold, degrees. */
function foldRange(fold: CFold): [number, number] {
  if (fold === 'quadrant') return [0, 90];
  if (fold === 'bilateral-c0') return [0, 180];
  if (fold === 'bilateral-c90') return [90, 270];
  return [0, 360];
}

/** C in degrees (any) folded as the shader folds it (profileFunction.ts). */
export function foldC(c: number, fold: CFold): number {
  let x = ((c % 360) + 360) % 360;
  if (fold === 'bilateral-c0' || fold === 'quadrant') x = x > 180 ? 360 - x : x;
  if (fold === 'quadrant') x = x > 90 ? 180 - x : x;
  if (fold === 'bilateral-c90') x = x < 90 ? 180 - x : x > 270 ? 540 - x : x;
  return x;
}

/**
 * The γ knots the dense grid must hold: the measured angles of the non-zero
 * support. The parser's zero skirt VERTICAL_PAD_DEG outside a partial range
 * (expandTypeC.ts) is not a knot: it would force a 0.01° step. Outside the
 * knots the lookup returns 0, so within that 0.01° band (and only there) the
 * table drops the file's ramp from I(edge) to 0 (the documented exception of
 * the 1e-4 bound; docs/baker.md).
 */
function gammaKnots(ph: Photometry): number[] {
  const v = ph.verticalAngles.length >= 2 ? ph.verticalAngles : [0, 180];
  const rows = ph.verticalAngles.length >= 2 ? ph.candela : ph.candela.map((r) => [r[0], r[0]]);
  const zero = (j: number) => rows.every((r) => !(r[j] > 0));
  let lo = 0;
  while (lo < v.length - 1 && zero(lo) && zero(lo + 1)) lo++;
  let hi = v.length - 1;
  while (hi > lo && zero(hi) && zero(hi - 1)) hi--;
  const isPad = (j: number, neighbour: number) => zero(j) && Math.abs(Math.abs(v[j] - v[neighbour]) - VERTICAL_PAD_DEG) < 1e-9 && !zero(neighbour);
  if (hi > lo && isPad(lo, lo + 1)) lo++;
  if (hi > lo && isPad(hi, hi - 1)) hi--;
  return v.slice(lo, hi + 1);
}

/** Resample one photometry once onto its dense grid, with the engine's own interpolation (core/photometry/intensity.ts). */
export function resampleProfile(ph: Photometry): DenseProfileGrid {
  const rotational = ph.horizontalAngles.length < 2;
  const fold = rotational ? 'none' : foldOf(ph);
  const g = alignedAxis(gammaKnots(ph), MAX_DENSE_GAMMA);
  let c: { axis: DenseAxis; aligned: boolean } | null = null;
  if (!rotational) {
    const [c0, c1] = foldRange(fold);
    const knots = [c0, ...ph.horizontalAngles.filter((a) => a > c0 + 1e-9 && a < c1 - 1e-9), c1];
    c = alignedAxis(knots, Math.max(2, Math.min(MAX_DENSE_C, Math.floor(MAX_DENSE_VALUES / g.axis.count))));
  }
  const planes = c ? c.axis.count : 1;
  const values = new Float32Array(planes * g.axis.count);
  for (let h = 0; h < planes; h++) {
    // Sample the last C exactly at the range end (first + (n−1)·step can round past it).
    const cDeg = c ? (h === planes - 1 ? foldRange(fold)[1] : c.axis.first + h * c.axis.step) : 0;
    for (let j = 0; j < g.axis.count; j++) {
      const gDeg = j === g.axis.count - 1 ? g.axis.first + (g.axis.count - 1) * g.axis.step : g.axis.first + j * g.axis.step;
      const cd = intensity(ph, Math.min(180, gDeg), cDeg);
      values[h * g.axis.count + j] = Number.isFinite(cd) && cd > 0 ? cd : 0;
    }
  }
  return { gamma: g.axis, c: c ? c.axis : null, fold, values, aligned: g.aligned && (c ? c.aligned : true) };
}

/** The dense grid's bilinear value at (γ, C), as the shader computes it (profileFunction.ts), in float64. */
export function denseIntensity(grid: DenseProfileGrid, gammaDeg: number, cDeg: number): number {
  const { gamma } = grid;
  const f = (gammaDeg - gamma.first) / gamma.step;
  const cutBelow = gamma.first > 1e-9;
  const cutAbove = gamma.first + (gamma.count - 1) * gamma.step < 180 - 1e-9;
  if ((cutBelow && f < -0.001) || (cutAbove && f > gamma.count - 1 + 0.001)) return 0;
  const fg = Math.min(Math.max(f, 0), gamma.count - 1);
  const vi = Math.min(Math.floor(fg), gamma.count - 2);
  const vt = fg - vi;
  const at = (h: number, j: number) => grid.values[h * gamma.count + j];
  if (!grid.c) return at(0, vi) * (1 - vt) + at(0, vi + 1) * vt;
  const fc = Math.min(Math.max((foldC(cDeg, grid.fold) - grid.c.first) / grid.c.step, 0), grid.c.count - 1);
  const hi = Math.min(Math.floor(fc), grid.c.count - 2);
  const ht = fc - hi;
  const a = at(hi, vi) * (1 - vt) + at(hi, vi + 1) * vt;
  const b = at(hi + 1, vi) * (1 - vt) + at(hi + 1, vi + 1) * vt;
  return a * (1 - ht) + b * ht;
}
