import { blockSumPass, KEYS_PER_ROUND, patchMaskPass, patchTablePass, tileKeyPass, topBlockPass, topMergePass } from '../../../shaders/brightSelection.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import type { BrightPatchOptions } from './brightPatchOptions';
import { createDataTexture } from './createDataTexture';
import type { CompilePass } from './createPassCompiler';
import { readRgbaRect, type FloatTarget } from './floatTarget';
import { PATCH_TABLE_WIDTH } from './patchTable';
import type { TileSumAtlas } from './readTileSums';
import { runPass } from './runPass';
import type { TargetPool } from './targetPool';

/** RGBA texels per row of the surface table. */
const SURFACE_ROW = 7;

/** Tiles per block edge in the reductions (16 × 16 tiles per fragment). */
const BLOCK = 16;

/** What the report says of a selection (bakeReport.ts). */
export interface BrightSummary {
  count: number;
  peakedness: number;
  residualPeakedness: number;
}

/** The bright patches chosen on the GPU: the patch table and the residual mask stay textures. */
export interface GpuBrightSelection {
  /** patchTable.ts's layout, `rows` rows: the patches, then the sentinel (surface index −1); row `rows` the summary. */
  table: FloatTarget;
  rows: number;
  /** Per tile of the atlas (same columns as the tile sums): 1 where the tile is a patch. */
  mask: FloatTarget;
  /** The summary for the report: one read-back of one texel (counted by `countRead`). */
  readSummary(countRead: (bytes: number) => void): BrightSummary;
  dispose(): void;
}

export const gpuTileKeys = tileKeyPass(LUMINANCE_WEIGHTS);
export const gpuPatchTable = patchTablePass(LUMINANCE_WEIGHTS);
/** The patch table where atlas charts are candidates (any frame, not only world axes). */
export const gpuChartPatchTable = patchTablePass(LUMINANCE_WEIGHTS, true);
export const gpuTopBlock = topBlockPass(LUMINANCE_WEIGHTS);

/**
 * Select the bright patches from the tile-sum atlas on the GPU, by selectBrightPatches.ts's rule
 * (docs/baker.md, "Bright patches selected on the GPU"):
 * 1. per tile its y = Y(ρ·Σ E·a), score Σ y²·a, global index g and area (tileKeyPass);
 * 2. the totals Σ y and Σ score by block sums to one texel;
 * 3. the ranked candidates by rounds of a top-k search: each round every block of 16 × 16 tiles
 *    keeps its first KEYS_PER_ROUND candidates after the last key found, and a merge keeps the
 *    first KEYS_PER_ROUND of all blocks (comparisons only: the CPU's order of the float32 scores);
 * 4. the compaction into the patch table: each texel runs the CPU's loop (stop at maxPatches or
 *    when the peakedness left is at most the target; skip a candidate under the contrast) up to
 *    its own row;
 * 5. the residual mask: the tiles whose index is in the table.
 * No read-back; `readSummary` reads the count and peakedness for the report.
 */
export function selectBrightPatchesOnGpu(gl: WebGL2RenderingContext, tiles: TileSumAtlas, options: BrightPatchOptions, compile: CompilePass, targets: Pick<TargetPool, 'acquire' | 'release'>): GpuBrightSelection {
  const { atlas, grids, rowsPerMode } = tiles;
  const surfaceTable = surfaceTableOf(gl, tiles);
  const area = grids.reduce((a, g) => a + g.frame.area, 0);
  const charts = grids.some((g) => g.frame.chart);
  const used: FloatTarget[] = [];
  const pool: PassPool = {
    acquire(w, h) {
      const t = targets.acquire(w, h, false);
      used.push(t);
      return t;
    },
    done(t) {
      targets.release(t);
      used.splice(used.indexOf(t), 1);
    },
  };
  const { done } = pool;

  // 1. Keys per tile.
  const keys = pool.acquire(atlas.width, rowsPerMode);
  runPass(gl, compile(gpuTileKeys, 'bright keys'), keys, { uSums: atlas.texture, uSurfaces: surfaceTable, uSurfaceCount: grids.length });
  // 2. Totals: block sums until one texel is left.
  const totals = blockTotals(gl, keys, compile, pool);
  // 3. Ranked candidates, KEYS_PER_ROUND per round; one round more than maxPatches needs covers a candidate the contrast test skips.
  const rounds = Math.ceil(options.maxPatches / KEYS_PER_ROUND) + 1;
  const list = rankedCandidates(gl, { keys, totals, tiles, surfaceTable, area, rounds }, options, compile, pool);

  // 4. The patch table (compaction), and the summary row.
  const rows = options.maxPatches;
  const table = pool.acquire(PATCH_TABLE_WIDTH, rows + 1);
  runPass(gl, compile(charts ? gpuChartPatchTable : gpuPatchTable, 'bright table'), table, {
    uList: list.texture,
    uSums: atlas.texture,
    uTotals: totals.texture,
    uSurfaces: surfaceTable,
    uSurfaceCount: grids.length,
    uListLength: rounds * KEYS_PER_ROUND,
    uRowsPerMode: rowsPerMode,
    uRows: rows,
    uMaxPatches: options.maxPatches,
    uArea: area,
    uTargetPeakedness: options.targetPeakedness,
    uMinContrast: options.minContrast,
  });
  done(list);
  done(totals);

  // 5. The residual mask.
  const mask = pool.acquire(atlas.width, rowsPerMode);
  runPass(gl, compile(patchMaskPass, 'bright mask'), mask, { uKeys: keys.texture, uPatches: table.texture, uRows: rows });
  done(keys);
  gl.deleteTexture(surfaceTable);

  return {
    table,
    rows,
    mask,
    readSummary(countRead) {
      const row = readRgbaRect(gl, table, 0, rows, 1, 1);
      countRead(row.byteLength);
      return { count: Math.round(row[0]), peakedness: row[1], residualPeakedness: row[2] };
    },
    dispose() {
      for (const t of [...used]) done(t);
    },
  };
}

/** Render targets taken for the selection and given back when done with. */
interface PassPool {
  acquire(width: number, height: number): FloatTarget;
  done(target: FloatTarget): void;
}

/** Per surface or chart seven RGBA texels: its tile grid, texel size, extent, first global tile, ρ and frame (what the passes read; shaders/brightSelection.glsl.ts). */
function surfaceTableOf(gl: WebGL2RenderingContext, { grids }: TileSumAtlas): WebGLTexture {
  const surfaces = new Float32Array(grids.length * SURFACE_ROW * 4);
  let first = 0;
  grids.forEach((g, s) => {
    const f = g.frame;
    const rho = f.reflectance;
    // World axis indices of a room surface of the box (texels 3 and 4's w; unused for a chart).
    const uAxis = f.chart ? 0 : f.axisU.indexOf(1);
    const vAxis = f.chart ? 0 : f.axisV.indexOf(1);
    const row = [g.column, g.tilesU, g.tilesV, g.tile, f.width, f.height, f.lengthU / f.width, f.lengthV / f.height, f.lengthU, f.lengthV, first, f.index];
    surfaces.set([...row, rho[0], rho[1], rho[2], uAxis, ...f.origin, vAxis, ...f.axisU, f.vSign, ...f.axisV, 0], s * SURFACE_ROW * 4);
    first += g.tilesU * g.tilesV;
  });
  return createDataTexture(gl, surfaces, SURFACE_ROW, grids.length, 4);
}

/** Σ y and Σ score of all tiles: BLOCK × BLOCK sums, level after level, down to one texel. */
function blockTotals(gl: WebGL2RenderingContext, keys: FloatTarget, compile: CompilePass, pool: PassPool): FloatTarget {
  const sum = compile(blockSumPass, 'bright totals');
  let level = keys;
  do {
    const next = pool.acquire(Math.ceil(level.width / BLOCK), Math.ceil(level.height / BLOCK));
    runPass(gl, sum, next, { uMap: level.texture, uBlock: BLOCK });
    if (level !== keys) pool.done(level);
    level = next;
  } while (level.width > 1 || level.height > 1);
  return level;
}

/** The candidates in the CPU's order, KEYS_PER_ROUND per round: each block's next ones after the last key found, then a merge of all blocks. */
function rankedCandidates(
  gl: WebGL2RenderingContext,
  input: { keys: FloatTarget; totals: FloatTarget; tiles: TileSumAtlas; surfaceTable: WebGLTexture; area: number; rounds: number },
  options: BrightPatchOptions,
  compile: CompilePass,
  pool: PassPool,
): FloatTarget {
  const { keys, totals, tiles, surfaceTable, area, rounds } = input;
  const pairs = KEYS_PER_ROUND / 2;
  const blocks = pool.acquire(Math.ceil(keys.width / BLOCK), Math.ceil(keys.height / BLOCK) * pairs);
  let list = pool.acquire(rounds * pairs, 1);
  let other = pool.acquire(rounds * pairs, 1);
  const topBlock = compile(gpuTopBlock, 'bright top-k');
  const topMerge = compile(topMergePass, 'bright top-k');
  for (let round = 0; round < rounds; round++) {
    runPass(gl, topBlock, blocks, {
      uKeys: keys.texture,
      uTotals: totals.texture,
      uList: list.texture,
      uSums: tiles.atlas.texture,
      uSurfaces: surfaceTable,
      uSurfaceCount: tiles.grids.length,
      uRound: round,
      uBlock: BLOCK,
      uArea: area,
      uMinContrast: options.minContrast,
      uMaxPatches: options.maxPatches,
      uTargetPeakedness: options.targetPeakedness,
    });
    runPass(gl, topMerge, other, { uBlocks: blocks.texture, uList: list.texture, uRound: round });
    [list, other] = [other, list];
  }
  pool.done(other);
  pool.done(blocks);
  return list;
}
