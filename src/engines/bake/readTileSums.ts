import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { tileSumPass } from '../../../shaders/tileSumPass.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import { readRgba, type FloatTarget } from './floatTarget';
import { runPass, type PassProgram } from './runPass';
import type { SurfaceTileSums } from './selectBrightPatches';
import type { SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';

/** Texels per tile edge for a target tile size (metres). */
export function tileTexels(layout: SurfaceLayout, tileSize: number): number {
  const texel = Math.max(layout.lengthU / layout.width, layout.lengthV / layout.height);
  return Math.max(1, Math.round(tileSize / texel));
}

/** The tile-sum pass as compiled for the baker's luminance weights. */
export const tileSums = tileSumPass(LUMINANCE_WEIGHTS);

/** One surface's tiles in the tile-sum atlas. */
export interface TileGrid {
  layout: SurfaceLayout;
  /** Texels per tile edge. */
  tile: number;
  tilesU: number;
  tilesV: number;
  /** Atlas column of the surface's first tile. */
  column: number;
}

/** The tile-sum atlas: every surface's sums (rows 0 … rowsPerMode − 1) and moments (rows rowsPerMode …) side by side. */
export interface TileSumAtlas {
  atlas: FloatTarget;
  grids: TileGrid[];
  rowsPerMode: number;
}

/**
 * Draw the tile sums and moments (shaders/tileSumPass.glsl.ts) of the direct maps of `surfaces`
 * into one atlas target from `targets` (the caller releases it).
 */
export function drawTileSums(
  gl: WebGL2RenderingContext,
  pass: PassProgram<typeof tileSums.uniforms>,
  surfaces: readonly SurfaceLayout[],
  reflectance: readonly Rgb[],
  direct: readonly FloatTarget[],
  tileSize: number,
  targets: Pick<TargetPool, 'acquire' | 'release'>,
): TileSumAtlas {
  let column = 0;
  const grids = surfaces.map((layout): TileGrid => {
    const tile = tileTexels(layout, tileSize);
    const tilesU = Math.ceil(layout.width / tile);
    const grid = { layout, tile, tilesU, tilesV: Math.ceil(layout.height / tile), column };
    column += tilesU;
    return grid;
  });
  const rowsPerMode = Math.max(...grids.map((g) => g.tilesV));
  // Every texel that is read (back, or by the GPU selection) is written first: no clear needed.
  const atlas = targets.acquire(column, 2 * rowsPerMode, false);
  for (const g of grids) {
    for (const mode of [0, 1]) {
      const y = mode * rowsPerMode;
      runPass(
        gl,
        pass,
        atlas,
        {
          uMap: direct[g.layout.index].texture,
          uOffset: [g.column, y],
          uTile: g.tile,
          uMode: mode,
          uTexel: [g.layout.lengthU / g.layout.width, g.layout.lengthV / g.layout.height],
          uRho: reflectance[g.layout.index],
        },
        [g.column, y, g.tilesU, g.tilesV],
      );
    }
  }
  return { atlas, grids, rowsPerMode };
}

/**
 * The tile sums and moments (shaders/tileSumPass.glsl.ts) of the direct maps
 * of `surfaces`, for the bright-patch selection on the CPU. Every surface's
 * sums (mode 0) and moments (mode 1) are drawn side by side into one atlas
 * target, so the whole selection costs one read-back (told to `countRead`).
 */
export function readTileSums(
  gl: WebGL2RenderingContext,
  pass: PassProgram<typeof tileSums.uniforms>,
  surfaces: readonly SurfaceLayout[],
  reflectance: readonly Rgb[],
  direct: readonly FloatTarget[],
  tileSize: number,
  targets: Pick<TargetPool, 'acquire' | 'release'>,
  countRead: (bytes: number) => void,
): SurfaceTileSums[] {
  const { atlas, grids, rowsPerMode } = drawTileSums(gl, pass, surfaces, reflectance, direct, tileSize, targets);
  const atlasWidth = atlas.width;
  const all = readRgba(gl, atlas);
  countRead(all.byteLength);
  targets.release(atlas);
  return grids.map((g) => {
    const cut = (mode: number) => {
      const out = new Float32Array(g.tilesU * g.tilesV * 4);
      for (let j = 0; j < g.tilesV; j++) {
        const from = ((mode * rowsPerMode + j) * atlasWidth + g.column) * 4;
        out.set(all.subarray(from, from + g.tilesU * 4), j * g.tilesU * 4);
      }
      return out;
    };
    return { layout: g.layout, tile: g.tile, tilesU: g.tilesU, tilesV: g.tilesV, reflectance: reflectance[g.layout.index], sums: cut(0), moments: cut(1) };
  });
}
