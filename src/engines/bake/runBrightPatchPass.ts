import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { brightGatherPass } from '../../../shaders/brightGatherPass.glsl';
import { occludedBrightGatherPass } from '../../../shaders/occludedBrightGatherPass.glsl';
import { residualPass } from '../../../shaders/residualPass.glsl';
import type { BrightPatchOptions } from './brightPatchOptions';
import type { FloatTarget } from './floatTarget';
import { createDataTexture } from './createDataTexture';
import { patchTable, PATCH_TABLE_WIDTH } from './patchTable';
import { readTileSums, tileSums } from './readTileSums';
import type { CompilePass } from './createPassCompiler';
import { runPass } from './runPass';
import { selectBrightPatches, type BrightSelection } from './selectBrightPatches';
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
  selection: BrightSelection;
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
 * targets come from the baker's pool (targetPool.ts); `countRead` is told
 * about the one read-back (the tile sums of all surfaces: the selection is
 * made on the CPU).
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
  const none: BrightPatchPass = {
    selection: { patches: [], peakedness: 1, residualPeakedness: 1 },
    residual: layouts.map(() => null),
    bright: layouts.map(() => null),
    dispose() {},
  };
  if (options.maxPatches <= 0) return none;
  const reflecting = layouts.filter((l) => reflectance[l.index].some((r) => r > 0));
  if (reflecting.length === 0) return none;
  const sums = readTileSums(gl, compile(tileSums, 'bright tiles'), reflecting, reflectance, direct, options.tileSize, targets, countRead);
  const selection = selectBrightPatches(sums, options);
  if (selection.patches.length === 0) return { ...none, selection };

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
    runPass(gl, compile(residualPass, 'bright residual'), out, { uMap: direct[layout.index].texture, uMask: maskTexture, uTile: s.tile });
    return out;
  });

  // Exact gather from the bright patches at every texel centre of every surface (and every covered atlas texel).
  const frame = (layout: SurfaceLayout) => ({
    uPatches: patchTexture,
    uPatchCount: n,
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
    if (selection.patches.every((p) => p.surface === layout.index)) return null;
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

  return {
    selection,
    residual,
    bright,
    dispose() {
      for (const t of made) targets.release(t);
      for (const t of textures) gl.deleteTexture(t);
    },
  };
}
