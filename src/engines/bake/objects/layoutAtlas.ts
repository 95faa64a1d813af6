/**
 * Where each chart goes in the objects' atlas and at what texel size (docs/baker.md, "Objects:
 * geometry"). A chart of w × h metres covers ⌈w/s⌉ × ⌈h/s⌉ texels at texel size s; its cell adds a
 * one-texel gutter on every side, so two charts are at least two texels apart and no chart touches
 * the atlas edge (bilinear lookups and the baker's dilation never mix two charts). When the cells do
 * not fit in maxAtlasSize², s grows by 1.25 until they do (square texels, one size for all charts;
 * the walls clamp each edge instead: docs/baker.md, "Texel size of walls and objects"). When they do
 * not fit even at one texel each (every chart's cell is at least 3 × 3 with its gutter, so a
 * furnished shop of 2 000 facets needs more than a 128² atlas at any texel size), the limit
 * doubles, up to ATLAS_CEILING, and the texel search starts again from the size asked for: a quality
 * level's limit is a wish for detail, not a reason to show no light at all.
 */
import { InputError } from '../../../core/inputError';
import type { Chart } from './buildCharts';
import { packCells } from './packCells';

/** Empty texels around each chart's texels, per side. */
export const CHART_GUTTER = 1;
/** Factor by which the texel size grows while the atlas does not fit. */
export const TEXEL_GROWTH = 1.25;
/** The largest atlas a limit is raised to: WebGL 2 guarantees MAX_TEXTURE_SIZE ≥ 2048 (OpenGL ES 3.0 §6.1.1, table 6.28). */
export const ATLAS_CEILING = 2048;

export interface AtlasLayout {
  /** Metres per texel actually used. */
  texelSize: number;
  width: number;
  height: number;
  /** Per chart: lower-left texel of its texels (inside the gutter) and its size in texels. */
  x: Int32Array;
  y: Int32Array;
  columns: Int32Array;
  rows: Int32Array;
}

/**
 * Texels a length of `metres` spans (at least 1). Up to 1e-4 texel over an integer does not add a
 * texel: float32 vertices make a 0.6 m face 0.6000001 m long. That hair is clipped from coverage.
 */
function texelsFor(metres: number, texelSize: number): number {
  return Math.max(1, Math.ceil(metres / texelSize - 1e-4));
}

export function layoutAtlas(charts: readonly Chart[], texelSize: number, maxAtlasSize: number): AtlasLayout {
  if (!(Number.isFinite(texelSize) && texelSize > 0)) throw new InputError(`objects: texel size must be a positive number of metres (got ${texelSize})`);
  if (!(Number.isInteger(maxAtlasSize) && maxAtlasSize >= 1 + 2 * CHART_GUTTER)) {
    throw new InputError(`objects: maxAtlasSize must be an integer of at least ${1 + 2 * CHART_GUTTER} texels (got ${maxAtlasSize})`);
  }
  const n = charts.length;
  const columns = new Int32Array(n);
  const rows = new Int32Array(n);
  const cellW = new Int32Array(n);
  const cellH = new Int32Array(n);
  for (let limit = maxAtlasSize; ; limit *= 2) {
    const layout = layoutWithin(charts, texelSize, limit, { columns, rows, cellW, cellH });
    if (layout) return layout;
    if (limit * 2 > Math.max(ATLAS_CEILING, maxAtlasSize)) {
      throw new InputError(`objects: ${n} planar charts do not fit in a ${limit} × ${limit} atlas even at one texel each; simplify the meshes or raise maxAtlasSize`);
    }
  }
}

/** The finest texel size from `texelSize` up (× TEXEL_GROWTH) whose cells pack into limit²; null when not even one texel per chart fits. */
function layoutWithin(charts: readonly Chart[], texelSize: number, limit: number, scratch: { columns: Int32Array; rows: Int32Array; cellW: Int32Array; cellH: Int32Array }): AtlasLayout | null {
  const { columns, rows, cellW, cellH } = scratch;
  for (let s = texelSize; ; s *= TEXEL_GROWTH) {
    let smallest = true;
    for (let i = 0; i < charts.length; i++) {
      columns[i] = texelsFor(charts[i].width, s);
      rows[i] = texelsFor(charts[i].height, s);
      smallest &&= columns[i] === 1 && rows[i] === 1;
      cellW[i] = columns[i] + 2 * CHART_GUTTER;
      cellH[i] = rows[i] + 2 * CHART_GUTTER;
    }
    const packed = packCells(cellW, cellH, limit);
    if (packed) {
      const x = packed.x.map((v) => v + CHART_GUTTER);
      const y = packed.y.map((v) => v + CHART_GUTTER);
      return { texelSize: s, width: packed.width, height: packed.height, x, y, columns: columns.slice(), rows: rows.slice() };
    }
    if (smallest) return null;
  }
}
