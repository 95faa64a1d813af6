import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { brightGatherPass } from '../../../shaders/brightGatherPass.glsl';
import { chartResidualPass } from '../../../shaders/chartTileSumPass.glsl';
import { occludedBrightGatherPass } from '../../../shaders/occludedBrightGatherPass.glsl';
import { residualPass } from '../../../shaders/residualPass.glsl';
import type { BrightPatchOptions } from './brightPatchOptions';
import type { FloatTarget } from './floatTarget';
import { createDataTexture } from './createDataTexture';
import { patchTable, PATCH_TABLE_WIDTH } from './patchTable';
import { chartTileSums, drawTileSums, readTileSums, tileSums, type ChartTileSource, type TileGrid } from './readTileSums';
import { selectBrightPatchesOnGpu, type BrightSummary } from './selectBrightPatchesOnGpu';
import type { CompilePass } from './createPassCompiler';
import { runPass } from './runPass';
import { selectBrightPatches } from './selectBrightPatches';
import { axisVector, type SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';
import type { TileFrame } from './tileFrame';

/**
 * "Bright patches": the first bounce from the small, very bright regions of
 * the direct maps, computed deterministically (docs/baker.md, "Stiff scenes:
 * bright patches"). The direct maps are tiled; the tiles that carry the heavy
 * tail of the Monte Carlo gather (largest Σ M²·A, M = ρ·E the exitance) are
 * taken out of the maps the gather samples (the residual maps) and their light
 * is gathered exactly instead: each becomes a uniformly emitting rectangle
 * with the tile's flux, its flux centroid and its second moments, and every
 * receiving texel adds M·F(dA → rectangle) with Lambert's exact
 * point-to-polygon form factor. The bounce is linear in the direct maps, so
 * splitting them into residual + bright parts changes nothing but the noise;
 * the only approximation is replacing a tile's exitance distribution by the
 * moment-matched rectangle (the same order as the bilinear map lookup it
 * replaces, and exact in flux: Σ over the receivers = the tile's reflected flux).
 */
export interface BrightPatchPass {
  /** The selection's count and peakedness for the report (chosen on the GPU: one read-back of one texel, counted by the pass's `countRead`). */
  summary(): BrightSummary;
  /** Per surface index (then the atlas, index 6, where its charts are candidates): the residual direct map (null: gather the direct map itself). */
  residual: (FloatTarget | null)[];
  /** Per surface index (then the objects' atlas, index 6, with objects): E from the bright patches at texel centres (null when there are none). */
  bright: (FloatTarget | null)[];
  dispose(): void;
}

/**
 * A scene's objects as the bright-patch pass sees them: occluders between patches and receivers,
 * and the atlas as one more receiver (shaders/occludedBrightGatherPass.glsl.ts). With `charts`
 * (a shaped room: its surfaces are atlas charts) the atlas's charts are candidates too, tiled in
 * their own planes (tileFrame.ts), and the atlas's first bounce gathers from its residual map;
 * without, patches are taken from the room surfaces' direct maps only and the atlas's first bounce
 * goes through the ordinary gather.
 */
export interface BrightPatchObjects {
  bvhWidth: number;
  atlasWidth: number;
  atlasHeight: number;
  uBvhNodes: WebGLTexture;
  uBvhTriangles: WebGLTexture;
  uPoints: WebGLTexture;
  uNormals: WebGLTexture;
  /** The charts as candidates (null: the room surfaces of the box only), the atlas's ρ per texel and its texel size. */
  charts: { frames: readonly TileFrame[]; reflectance: WebGLTexture; texelSize: number } | null;
}

/**
 * Run the tile pass on the direct maps, select the bright patches, and build
 * the residual maps and the bright-patch illuminance per surface. Render
 * targets come from the baker's pool (targetPool.ts). With `options.onGpu` the
 * selection stays on the GPU (selectBrightPatchesOnGpu.ts: no read-back; every
 * reflecting surface gets a residual map and every surface a bright map, since
 * which ones hold patches is not known on the CPU); otherwise `countRead` is told
 * about the one read-back of the tile sums and the selection is made on the CPU.
 * `atlasDirect`: the atlas's direct map, tiled chart by chart where `objects.charts` is set.
 */
export function runBrightPatchPass(
  gl: WebGL2RenderingContext,
  layouts: SurfaceLayout[],
  reflectance: Rgb[],
  direct: FloatTarget[],
  options: BrightPatchOptions,
  compile: CompilePass,
  countRead: (bytes: number) => void,
  targets: Pick<TargetPool, 'acquire' | 'release'>,
  objects: BrightPatchObjects | null = null,
  atlasDirect: FloatTarget | null = null,
): BrightPatchPass {
  const noSummary: BrightSummary = { count: 0, peakedness: 1, residualPeakedness: 1 };
  const none: BrightPatchPass = {
    summary: () => noSummary,
    residual: layouts.map(() => null),
    bright: layouts.map(() => null),
    dispose() {},
  };
  if (options.maxPatches <= 0) return none;
  const reflecting = layouts.filter((l) => reflectance[l.index].some((r) => r > 0));
  const charts = chartSource(objects, atlasDirect, compile);
  if (reflecting.length === 0 && !charts) return none;
  const job: BrightJob = { gl, layouts, reflecting, reflectance, direct, options, compile, countRead, targets, objects, charts, atlasDirect };
  return options.onGpu ? brightOnGpu(job) : brightOnCpu(job);
}

/** Everything one bright-patch pass reads. */
interface BrightJob {
  gl: WebGL2RenderingContext;
  layouts: SurfaceLayout[];
  reflecting: SurfaceLayout[];
  reflectance: Rgb[];
  direct: FloatTarget[];
  options: BrightPatchOptions;
  compile: CompilePass;
  countRead: (bytes: number) => void;
  targets: Pick<TargetPool, 'acquire' | 'release'>;
  objects: BrightPatchObjects | null;
  charts: ChartTileSource | null;
  atlasDirect: FloatTarget | null;
}

/** The atlas's charts as candidates (null where the scene's charts are not: a box room, or no chart reflects). */
function chartSource(objects: BrightPatchObjects | null, atlasDirect: FloatTarget | null, compile: CompilePass): ChartTileSource | null {
  if (!objects?.charts || !atlasDirect || objects.charts.frames.length === 0) return null;
  const { frames, reflectance, texelSize } = objects.charts;
  return { frames, pass: compile(chartTileSums, 'bright tiles'), direct: atlasDirect.texture, points: objects.uPoints, normals: objects.uNormals, reflectance, texelSize };
}

/** The pass with the selection on the CPU (selectBrightPatches.ts): one read-back of the tile sums. */
function brightOnCpu(job: BrightJob): BrightPatchPass {
  const { gl, layouts, reflecting, reflectance, direct, options, compile, countRead, targets, objects, charts } = job;
  const read = readTileSums(gl, compile(tileSums, 'bright tiles'), reflecting, reflectance, direct, options.tileSize, targets, countRead, charts);
  const selection = selectBrightPatches(read.sums, options);
  const summary: BrightSummary = { count: selection.patches.length, peakedness: selection.peakedness, residualPeakedness: selection.residualPeakedness };
  if (selection.patches.length === 0) return { summary: () => summary, residual: layouts.map(() => null), bright: layouts.map(() => null), dispose() {} };

  const n = selection.patches.length;
  const patchTexture = createDataTexture(gl, patchTable(selection.patches), PATCH_TABLE_WIDTH, n, 4);
  const made: FloatTarget[] = [];
  const textures: WebGLTexture[] = [patchTexture];
  // One mask over the tile-sum atlas's columns (as the GPU selection's): 1 on the tiles taken.
  const mask = new Float32Array(read.columns * read.rowsPerMode * 4);
  for (const p of selection.patches) {
    const grid = read.grids.find((g) => g.frame.index === p.surface)!;
    mask[4 * (p.tileV * read.columns + grid.column + p.tileU)] = 1;
  }
  const maskTexture = createDataTexture(gl, mask, read.columns, read.rowsPerMode, 4);
  textures.push(maskTexture);

  // Residual maps: the bright tiles cut out of the direct maps they lie on.
  const residual = layouts.map((layout): FloatTarget | null => {
    if (!selection.patches.some((p) => p.surface === layout.index)) return null;
    const grid = read.grids.find((g) => g.frame.index === layout.index)!;
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    runPass(gl, compile(residualPass, 'bright residual'), out, { uMap: direct[layout.index].texture, uMask: maskTexture, uTile: grid.tile, uMaskOffset: [grid.column, 0] });
    return out;
  });
  const onCharts = selection.patches.some((p) => read.grids.find((g) => g.frame.index === p.surface)?.frame.chart);
  if (onCharts) residual.push(atlasResidual(job, read.grids, maskTexture, made));
  const skip = (layout: SurfaceLayout) => selection.patches.every((p) => p.surface === layout.index);
  const bright = gatherBright(gl, layouts, patchTexture, n, skip, compile, targets, objects, made, charts !== null);
  return {
    summary: () => summary,
    residual,
    bright,
    dispose() {
      for (const t of made) targets.release(t);
      for (const t of textures) gl.deleteTexture(t);
    },
  };
}

/** The atlas's residual direct map: a copy of its direct map, then each chart's bright tiles zeroed in the chart's viewport. */
function atlasResidual(job: BrightJob, grids: readonly TileGrid[], mask: WebGLTexture, made: FloatTarget[]): FloatTarget {
  const { gl, compile, targets } = job;
  const atlasDirect = job.atlasDirect!;
  const pass = compile(chartResidualPass, 'bright residual');
  const out = targets.acquire(atlasDirect.width, atlasDirect.height, false);
  made.push(out);
  const values = { uMap: atlasDirect.texture, uMask: mask, uTile: 1, uMaskOffset: [0, 0] as const, uChartCorner: [0, 0] as const, uMasked: 0 };
  runPass(gl, pass, out, values);
  for (const g of grids) {
    const chart = g.frame.chart;
    if (!chart) continue;
    const masked = { ...values, uTile: g.tile, uMaskOffset: [g.column, 0] as const, uChartCorner: [chart.x, chart.y] as const, uMasked: 1 };
    runPass(gl, pass, out, masked, [chart.x, chart.y, g.frame.width, g.frame.height]);
  }
  return out;
}

/** The pass with the selection on the GPU: the patch table and the residual mask never leave it. */
function brightOnGpu(job: BrightJob): BrightPatchPass {
  const { gl, layouts, reflecting, reflectance, direct, options, compile, countRead, targets, objects, charts } = job;
  const tiles = drawTileSums(gl, compile(tileSums, 'bright tiles'), reflecting, reflectance, direct, options.tileSize, targets, charts);
  const selected = selectBrightPatchesOnGpu(gl, tiles, options, compile, targets);
  targets.release(tiles.atlas);
  const made: FloatTarget[] = [];
  const residualProgram = compile(residualPass, 'bright residual');
  const residual = layouts.map((layout): FloatTarget | null => {
    const grid = tiles.grids.find((g) => g.frame.index === layout.index);
    if (!grid) return null;
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    runPass(gl, residualProgram, out, { uMap: direct[layout.index].texture, uMask: selected.mask.texture, uTile: grid.tile, uMaskOffset: [grid.column, 0] });
    return out;
  });
  if (charts) residual.push(atlasResidual(job, tiles.grids, selected.mask.texture, made));
  const bright = gatherBright(gl, layouts, selected.table.texture, selected.rows, () => false, compile, targets, objects, made, charts !== null);
  let summary: BrightSummary | null = null;
  return {
    summary: () => (summary ??= selected.readSummary(countRead)),
    residual,
    bright,
    dispose() {
      for (const t of made) targets.release(t);
      selected.dispose();
    },
  };
}

/**
 * The exact gather from the patch table (`rows` rows, or fewer up to a sentinel) at every texel
 * centre of every surface that `skip` does not exclude, then of every covered atlas texel.
 */
function gatherBright(
  gl: WebGL2RenderingContext,
  layouts: SurfaceLayout[],
  patchTexture: WebGLTexture,
  rows: number,
  skip: (layout: SurfaceLayout) => boolean,
  compile: CompilePass,
  targets: Pick<TargetPool, 'acquire' | 'release'>,
  objects: BrightPatchObjects | null,
  made: FloatTarget[],
  charts: boolean,
): (FloatTarget | null)[] {
  const frame = (layout: SurfaceLayout) => ({
    uPatches: patchTexture,
    uPatchCount: rows,
    uOrigin: layout.origin,
    uAxisU: axisVector(layout.uAxisIndex, layout.lengthU),
    uAxisV: axisVector(layout.vAxisIndex, layout.lengthV),
    uNormal: layout.normal,
    uResolution: [layout.width, layout.height] as const,
    uSurface: layout.index,
  });
  const gather = objects ? null : compile(brightGatherPass, 'bright gather');
  const occluded = objects ? compile(occludedBrightGatherPass(objects.bvhWidth, charts), 'bright gather') : null;
  const objectValues = objects ? { uBvhNodes: objects.uBvhNodes, uBvhTriangles: objects.uBvhTriangles, uPoints: objects.uPoints, uNormals: objects.uNormals } : null;
  const bright = layouts.map((layout): FloatTarget | null => {
    if (skip(layout)) return null;
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    if (occluded && objectValues) runPass(gl, occluded, out, { ...frame(layout), ...objectValues, uFromAtlas: 0 });
    else runPass(gl, gather!, out, frame(layout));
    return out;
  });
  if (occluded && objects && objectValues) {
    const out = targets.acquire(objects.atlasWidth, objects.atlasHeight, false);
    made.push(out);
    // The frame uniforms are unused for the atlas (uFromAtlas = 1); uSurface −1 skips no patch.
    runPass(gl, occluded, out, { ...frame(layouts[0]), uSurface: -1, ...objectValues, uFromAtlas: 1 });
    bright.push(out);
  }
  return bright;
}
