import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { brightGatherPass } from '../../../shaders/brightGatherPass.glsl';
import { occludedBrightGatherPass } from '../../../shaders/occludedBrightGatherPass.glsl';
import { residualPass } from '../../../shaders/residualPass.glsl';
import type { BrightPatchOptions } from './brightPatchOptions';
import type { FloatTarget } from './floatTarget';
import { createDataTexture } from './createDataTexture';
import { patchTable, PATCH_TABLE_WIDTH } from './patchTable';
import { drawTileSums, readTileSums, tileSums } from './readTileSums';
import { selectBrightPatchesOnGpu, type BrightSummary } from './selectBrightPatchesOnGpu';
import type { CompilePass } from './createPassCompiler';
import { runPass } from './runPass';
import { selectBrightPatches } from './selectBrightPatches';
import { axisVector, type SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';

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
  /** Per surface index: the residual direct map (null: gather the direct map itself). */
  residual: (FloatTarget | null)[];
  /** Per surface index (then the objects' atlas, index 6, with objects): E from the bright patches at texel centres (null when there are none). */
  bright: (FloatTarget | null)[];
  dispose(): void;
}

/**
 * A scene's objects as the bright-patch pass sees them: occluders between patches and receivers,
 * and the atlas as one more receiver (shaders/occludedBrightGatherPass.glsl.ts). Patches are still
 * taken from the room surfaces' direct maps only: the atlas's first bounce goes through the
 * ordinary gather.
 */
export interface BrightPatchObjects {
  bvhWidth: number;
  atlasWidth: number;
  atlasHeight: number;
  uBvhNodes: WebGLTexture;
  uBvhTriangles: WebGLTexture;
  uPoints: WebGLTexture;
  uNormals: WebGLTexture;
}

/**
 * Run the tile pass on the direct maps, select the bright patches, and build
 * the residual maps and the bright-patch illuminance per surface. Render
 * targets come from the baker's pool (targetPool.ts). With `options.onGpu` the
 * selection stays on the GPU (selectBrightPatchesOnGpu.ts: no read-back; every
 * reflecting surface gets a residual map and every surface a bright map, since
 * which ones hold patches is not known on the CPU); otherwise `countRead` is told
 * about the one read-back of the tile sums and the selection is made on the CPU.
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
  if (reflecting.length === 0) return none;
  if (options.onGpu) return brightOnGpu(gl, layouts, reflecting, reflectance, direct, options, compile, countRead, targets, objects);
  const sums = readTileSums(gl, compile(tileSums, 'bright tiles'), reflecting, reflectance, direct, options.tileSize, targets, countRead);
  const selection = selectBrightPatches(sums, options);
  const summary: BrightSummary = { count: selection.patches.length, peakedness: selection.peakedness, residualPeakedness: selection.residualPeakedness };
  if (selection.patches.length === 0) return { ...none, summary: () => summary };

  const n = selection.patches.length;
  const patchTexture = createDataTexture(gl, patchTable(selection.patches, layouts), PATCH_TABLE_WIDTH, n, 4);
  const made: FloatTarget[] = [];
  const textures: WebGLTexture[] = [patchTexture];

  // Residual maps: the bright tiles cut out of the direct maps they lie on.
  const residual = layouts.map((layout): FloatTarget | null => {
    const own = selection.patches.filter((p) => p.surface === layout.index);
    if (own.length === 0) return null;
    const s = sums.find((x) => x.layout.index === layout.index)!;
    const mask = new Float32Array(s.tilesU * s.tilesV * 4);
    for (const p of own) mask[4 * (p.tileV * s.tilesU + p.tileU)] = 1;
    const maskTexture = createDataTexture(gl, mask, s.tilesU, s.tilesV, 4);
    textures.push(maskTexture);
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    runPass(gl, compile(residualPass, 'bright residual'), out, { uMap: direct[layout.index].texture, uMask: maskTexture, uTile: s.tile, uMaskOffset: [0, 0] });
    return out;
  });
  const bright = gatherBright(gl, layouts, patchTexture, n, (layout) => selection.patches.every((p) => p.surface === layout.index), compile, targets, objects, made);
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

/** The pass with the selection on the GPU: the patch table and the residual mask never leave it. */
function brightOnGpu(
  gl: WebGL2RenderingContext,
  layouts: SurfaceLayout[],
  reflecting: SurfaceLayout[],
  reflectance: Rgb[],
  direct: FloatTarget[],
  options: BrightPatchOptions,
  compile: CompilePass,
  countRead: (bytes: number) => void,
  targets: Pick<TargetPool, 'acquire' | 'release'>,
  objects: BrightPatchObjects | null,
): BrightPatchPass {
  const tiles = drawTileSums(gl, compile(tileSums, 'bright tiles'), reflecting, reflectance, direct, options.tileSize, targets);
  const selected = selectBrightPatchesOnGpu(gl, tiles, reflectance, options, compile, targets);
  targets.release(tiles.atlas);
  const made: FloatTarget[] = [];
  const residualProgram = compile(residualPass, 'bright residual');
  const residual = layouts.map((layout): FloatTarget | null => {
    const grid = tiles.grids.find((g) => g.layout.index === layout.index);
    if (!grid) return null;
    const out = targets.acquire(layout.width, layout.height, false);
    made.push(out);
    runPass(gl, residualProgram, out, { uMap: direct[layout.index].texture, uMask: selected.mask.texture, uTile: grid.tile, uMaskOffset: [grid.column, 0] });
    return out;
  });
  const bright = gatherBright(gl, layouts, selected.table.texture, selected.rows, () => false, compile, targets, objects, made);
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
  const occluded = objects ? compile(occludedBrightGatherPass(objects.bvhWidth), 'bright gather') : null;
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
