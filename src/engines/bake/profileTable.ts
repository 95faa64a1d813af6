import type { Photometry } from '../../core/photometry/types';
import { resampleProfile, type CFold, type DenseAxis } from './denseProfileGrid';

/** Width of the R32F data texture that holds every profile's tables (WebGL2 guarantees 2048). */
export const DATA_TEXTURE_WIDTH = 2048;

/**
 * Where one angle axis of a profile lives in the data texture and how the
 * shader finds the grid cell of an angle:
 * - `uniform`: equal steps, the cell is (a − first)/step: no memory access;
 * - `mapped`: non-uniform steps; a lookup table of `mapSize` bins of
 *   `1/mapScale` degrees gives, for each bin, the last grid angle ≤ the bin's
 *   start. The bin width never exceeds the smallest grid step, so at most one
 *   grid angle falls inside a bin and one comparison with the stored angles
 *   finds the exact cell. Interpolation then uses the true angles: the
 *   result is the exact bilinear interpolation of the measured grid, which
 *   resampling to a uniform grid would only approximate (a 1° spot measured
 *   at 0.5° would lose its peak shape).
 */
export interface AxisLayout {
  count: number;
  first: number;
  last: number;
  anglesOffset: number;
  uniform: boolean;
  /** uniform: 1/step; mapped: bins per degree. */
  invStep: number;
  mapOffset: number;
  mapSize: number;
  /** Smallest step between grid angles, degrees. */
  minStep: number;
}

/** The measured grid as the file gives it, found by bin tables (`profileLookup: 'measured'`). */
export interface MeasuredLookup {
  kind: 'measured';
  vertical: AxisLayout;
  /** null for rotationally symmetric profiles: one C plane, a 1D lookup. */
  horizontal: AxisLayout | null;
  /** candela[h][v] stored at candelaOffset + h·vertical.count + v. */
  candelaOffset: number;
}

/** The profile resampled once onto a uniform (γ, C) grid (denseProfileGrid.ts): four fetches, no search (the default). */
export interface DenseLookup {
  kind: 'dense';
  gamma: DenseAxis;
  /** null for rotationally symmetric profiles. */
  c: DenseAxis | null;
  fold: CFold;
  /** values[h][g] stored at offset + h·gamma.count + g. */
  offset: number;
}

/** How the direct pass looks candela up: 'dense' (default) or 'measured' (the file's grid with bin tables; kept for comparison). */
export type ProfileLookupMode = 'dense' | 'measured';

export interface ProfileLayout {
  /** Index among the scene's distinct profiles (GLSL names use it). */
  id: number;
  lookup: MeasuredLookup | DenseLookup;
  /** Largest γ (degrees) at which interpolated intensity can be non-zero, and the smallest. */
  gammaMax: number;
  gammaMin: number;
  peakCandela: number;
  /**
   * Angular scale of the distribution, degrees: peak candela / steepest change
   * per degree along γ (∞ for a constant one). The direct pass sub-samples a
   * texel finely enough to resolve a few such scales (generateDirectShader.ts).
   */
  featureAngle: number;
}

export interface ProfileTable {
  layouts: ProfileLayout[];
  /** Texel data, DATA_TEXTURE_WIDTH × rows, R32F. */
  data: Float32Array;
  rows: number;
}

/** Largest lookup table per axis; grids finer than this fall back to a table of this size plus a short search. */
const MAX_MAP_SIZE = 8192;

function isUniform(angles: number[]): boolean {
  const step = (angles[angles.length - 1] - angles[0]) / (angles.length - 1);
  return angles.every((a, i) => Math.abs(a - (angles[0] + i * step)) <= 1e-6 * Math.max(1, Math.abs(step)));
}

/** Pack the given profiles (each once, in order) into one float table. */
export function buildProfileTable(profiles: Photometry[], mode: ProfileLookupMode = 'dense'): ProfileTable {
  const values: number[] = [];
  const layouts = profiles.map((ph, id): ProfileLayout => {
    // A single vertical angle cannot be interpolated: treat it as a flat profile over 0..180.
    const vAngles = ph.verticalAngles.length >= 2 ? ph.verticalAngles : [0, 180];
    const planes = ph.candela.map((row) => (ph.verticalAngles.length >= 2 ? row : [row[0], row[0]]));
    const rotational = ph.horizontalAngles.length < 2;
    const usedPlanes = rotational ? planes.slice(0, 1) : planes;
    const lookup = mode === 'measured' ? measuredLookup(ph, vAngles, usedPlanes, rotational, values) : denseLookup(ph, values);
    return { id, lookup, ...profileExtent(vAngles, usedPlanes) };
  });
  const rows = Math.max(1, Math.ceil(values.length / DATA_TEXTURE_WIDTH));
  const data = new Float32Array(rows * DATA_TEXTURE_WIDTH);
  data.set(values);
  return { layouts, data, rows };
}

/** Appends `xs` to the table; returns where they start. */
function push(values: number[], xs: ArrayLike<number>): number {
  const offset = values.length;
  for (let i = 0; i < xs.length; i++) values.push(xs[i]);
  return offset;
}

/** Candela below zero or not finite count as none. */
const safeCandela = (cd: number): number => (Number.isFinite(cd) && cd > 0 ? cd : 0);

/** The file's grid: vertical axis, horizontal axis (none when rotational), then the candela, appended in that order. */
function measuredLookup(ph: Photometry, vAngles: number[], usedPlanes: number[][], rotational: boolean, values: number[]): MeasuredLookup {
  const vertical = axisLayout(vAngles, values);
  const horizontal = rotational ? null : axisLayout(ph.horizontalAngles, values);
  const candelaOffset = values.length;
  for (const row of usedPlanes) for (const cd of row) values.push(safeCandela(cd));
  return { kind: 'measured', vertical, horizontal, candelaOffset };
}

function denseLookup(ph: Photometry, values: number[]): DenseLookup {
  const grid = resampleProfile(ph);
  return { kind: 'dense', gamma: grid.gamma, c: grid.c, fold: grid.fold, offset: push(values, grid.values) };
}

/** One measured axis: its angles appended, and for non-uniform steps the bin table that finds a cell (see AxisLayout). */
function axisLayout(angles: number[], values: number[]): AxisLayout {
  const count = angles.length;
  const first = angles[0];
  const last = angles[count - 1];
  const anglesOffset = push(values, angles);
  if (count < 2 || isUniform(angles)) {
    return { count, first, last, anglesOffset, uniform: true, invStep: count < 2 ? 0 : (count - 1) / (last - first), mapOffset: 0, mapSize: 0, minStep: count < 2 ? 0 : (last - first) / (count - 1) };
  }
  let minStep = Infinity;
  for (let i = 1; i < count; i++) minStep = Math.min(minStep, angles[i] - angles[i - 1]);
  const span = last - first;
  const mapSize = Math.min(MAX_MAP_SIZE, Math.ceil(span / minStep) + 1);
  const binsPerDegree = mapSize / span;
  const map = new Float32Array(mapSize);
  let k = 0;
  for (let b = 0; b < mapSize; b++) {
    const start = first + b / binsPerDegree;
    while (k < count - 2 && angles[k + 1] <= start) k++;
    map[b] = k;
  }
  return { count, first, last, anglesOffset, uniform: false, invStep: binsPerDegree, mapOffset: push(values, map), mapSize, minStep };
}

/** Where a profile can be non-zero (γ range), its peak, and its angular feature scale (see ProfileLayout). */
function profileExtent(vAngles: number[], usedPlanes: number[][]): Pick<ProfileLayout, 'gammaMax' | 'gammaMin' | 'peakCandela' | 'featureAngle'> {
  let peak = 0;
  let firstNonZero = vAngles.length;
  let lastNonZero = -1;
  for (const row of usedPlanes) {
    row.forEach((cd, v) => {
      const safe = safeCandela(cd);
      if (safe > 0) {
        peak = Math.max(peak, safe);
        firstNonZero = Math.min(firstNonZero, v);
        lastNonZero = Math.max(lastNonZero, v);
      }
    });
  }
  // Interpolation reaches zero only at the neighbouring grid angle.
  const gammaMax = lastNonZero < 0 ? 0 : vAngles[Math.min(vAngles.length - 1, lastNonZero + 1)];
  const gammaMin = lastNonZero < 0 ? 180 : vAngles[Math.max(0, firstNonZero - 1)];
  let steepest = 0;
  for (const row of usedPlanes) {
    for (let v = 1; v < row.length; v++) {
      const step = vAngles[v] - vAngles[v - 1];
      if (step > 0) steepest = Math.max(steepest, Math.abs(safeCandela(row[v]) - safeCandela(row[v - 1])) / step);
    }
  }
  const featureAngle = steepest > 0 ? peak / steepest : Infinity;
  return { gammaMax: lastNonZero === vAngles.length - 1 ? 180 : gammaMax, gammaMin: firstNonZero === 0 ? 0 : gammaMin, peakCandela: peak, featureAngle };
}
