import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { chartTileSumPass } from '../../../shaders/chartTileSumPass.glsl';
import { tileSumPass } from '../../../shaders/tileSumPass.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import { readRgba, type FloatTarget } from './floatTarget';
import { runPass, type PassProgram } from './runPass';
import type { SurfaceTileSums } from './selectBrightPatches';
import type { SurfaceLayout } from './surfaceLayout';
import type { TargetPool } from './targetPool';
import { layoutTileFrame, type TileFrame } from './tileFrame';

/** Texels per tile edge for a target tile size (metres). */
export function tileTexels(layout: Pick<SurfaceLayout, 'lengthU' | 'lengthV' | 'width' | 'height'>, tileSize: number): number {
  const texel = Math.max(layout.lengthU / layout.width, layout.lengthV / layout.height);
  return Math.max(1, Math.round(tileSize / texel));
}

/** The tile-sum pass as compiled for the baker's luminance weights. */
export const tileSums = tileSumPass(LUMINANCE_WEIGHTS);
/** The same for a chart of the objects' atlas (its texels' own ρ, coverage and chart id). */
export const chartTileSums = chartTileSumPass(LUMINANCE_WEIGHTS);

/**
 * The charts of the objects' atlas as candidates of the bright-patch search (a shaped room's
 * surfaces and its furniture): their frames, the atlas's direct map and G-buffer, and the pass.
 */
export interface ChartTileSource {
  frames: readonly TileFrame[];
  pass: PassProgram<typeof chartTileSums.uniforms>;
  direct: WebGLTexture;
  points: WebGLTexture;
  normals: WebGLTexture;
  reflectance: WebGLTexture;
  texelSize: number;
}

/** One surface's (or chart's) tiles in the tile-sum atlas. */
export interface TileGrid {
  frame: TileFrame;
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
  charts: ChartTileSource | null = null,
): TileSumAtlas {
  let column = 0;
  const frames = [...surfaces.map((layout) => layoutTileFrame(layout, reflectance[layout.index])), ...(charts?.frames ?? [])];
  const grids = frames.map((frame): TileGrid => {
    const tile = tileTexels(frame, tileSize);
    const tilesU = Math.ceil(frame.width / tile);
    const grid = { frame, tile, tilesU, tilesV: Math.ceil(frame.height / tile), column };
    column += tilesU;
    return grid;
  });
  const rowsPerMode = Math.max(...grids.map((g) => g.tilesV));
  // Every texel that is read (back, or by the GPU selection) is written first: no clear needed.
  const atlas = targets.acquire(column, 2 * rowsPerMode, false);
  for (const g of grids) {
    for (const mode of [0, 1]) {
      const y = mode * rowsPerMode;
      const viewport: [number, number, number, number] = [g.column, y, g.tilesU, g.tilesV];
      const { frame } = g;
      if (frame.chart && charts) {
        const values = {
          uMap: charts.direct,
          uPoints: charts.points,
          uNormals: charts.normals,
          uRho: charts.reflectance,
          uOffset: [g.column, y] as const,
          uChartCorner: [frame.chart.x, frame.chart.y] as const,
          uChartSize: [frame.width, frame.height] as const,
          uChartId: frame.chart.id,
          uTile: g.tile,
          uMode: mode,
          uTexel: charts.texelSize,
        };
        runPass(gl, charts.pass, atlas, values, viewport);
        continue;
      }
      const values = {
        uMap: direct[frame.index].texture,
        uOffset: [g.column, y] as const,
        uTile: g.tile,
        uMode: mode,
        uTexel: [frame.lengthU / frame.width, frame.lengthV / frame.height] as const,
        uRho: frame.reflectance,
      };
      runPass(gl, pass, atlas, values, viewport);
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
  charts: ChartTileSource | null = null,
): { sums: SurfaceTileSums[]; grids: TileGrid[]; rowsPerMode: number; columns: number } {
  const { atlas, grids, rowsPerMode } = drawTileSums(gl, pass, surfaces, reflectance, direct, tileSize, targets, charts);
  const atlasWidth = atlas.width;
  const all = readRgba(gl, atlas);
  countRead(all.byteLength);
  targets.release(atlas);
  const sums = grids.map((g) => {
    const cut = (mode: number) => {
      const out = new Float32Array(g.tilesU * g.tilesV * 4);
      for (let j = 0; j < g.tilesV; j++) {
        const from = ((mode * rowsPerMode + j) * atlasWidth + g.column) * 4;
        out.set(all.subarray(from, from + g.tilesU * 4), j * g.tilesU * 4);
      }
      return out;
    };
    return { frame: g.frame, tile: g.tile, tilesU: g.tilesU, tilesV: g.tilesV, sums: cut(0), moments: cut(1) };
  });
  return { sums, grids, rowsPerMode, columns: atlasWidth };
}
