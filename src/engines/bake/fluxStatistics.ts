import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { fluxRatioPass, reduceSumPass, seriesRatioPass, REDUCE_GRID } from '../../../shaders/fluxReduce.glsl';
import { objectFluxRatioPass, objectReduceSumPass, objectReflectedFluxPass } from '../../../shaders/objectFluxReduce.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import { maxFluxRatio, type FluxRecord } from './fluxRecord';
import { readRgba, type FloatTarget } from './floatTarget';
import { passProgram, runPass } from './runPass';
import type { TargetPool } from './targetPool';
import { texelArea, type SurfaceLayout } from './surfaceLayout';

export type { FluxRecord } from './fluxRecord';

/**
 * Flux statistics of the bounce maps, kept on the GPU (issue: no CPU–GPU
 * round trip inside a bake). `record(index, maps, scale)` reduces the six maps
 * to at most REDUCE_GRID² partial sums per surface, and one fused pass adds
 * them up and writes fluxRecord's (r_R, r_G, r_B, Φ_Y) into texel `index` of
 * a stats row; the tail combine samples that row directly. `read()` fetches
 * the whole row in one read-back (report time only).
 */
export interface FluxStatistics {
  /** Row texture: texel i = record i (RGBA32F, width = capacity). */
  readonly stats: FloatTarget;
  /** `maps`: the six surfaces' maps, then the atlas's when the bake has objects. */
  record(index: number, maps: FloatTarget[], scale: number): void;
  /** Records 0..count−1, in one readPixels of `capacity` texels. */
  read(count: number): FluxRecord[];
  dispose(): void;
}

/**
 * The objects' atlas as a seventh receiver (shaders/objectFluxReduce.glsl.ts): its flux is
 * Σ E·coverage·texel² and its reflected flux Σ ρ·E·coverage·texel², ρ per texel, so the
 * flux-weighted r of the tail includes the objects.
 */
export interface FluxObjects {
  width: number;
  height: number;
  texelSize: number;
  /** G-buffer point texture (a = coverage) and reflectance texture. */
  points: WebGLTexture;
  reflectance: WebGLTexture;
  maxReflectance: number;
}

/**
 * `openings`: the room lets light out — a shaped room with an opening, whose surfaces are the
 * objects' atlas and whose six box surfaces are the enclosure's black sinks. Then the sinks are
 * left out of Φ (they are no surfaces: one texel's E times a whole face is not the flux through the
 * openings; it counted the escape 8× in the daylight box), record 0 is the flux-weighted
 * reflectance of the room's surfaces, and record k ≥ 1 the ratio of successive reflected fluxes
 * R_k / R_{k−1} (shaders/fluxReduce.glsl.ts seriesRatioPass; R per record kept in a second row),
 * which contains what leaves through the openings (fluxRecord.ts, openRoomRecord). Without
 * openings every pass is as it was.
 */
export function createFluxStatistics(
  gl: WebGL2RenderingContext,
  pool: TargetPool,
  layouts: SurfaceLayout[],
  reflectance: Rgb[],
  capacity: number,
  onRead: (bytes: number) => void,
  objects: FluxObjects | null = null,
  openings = false,
): FluxStatistics {
  const maxRatio = Math.min(Math.max(maxFluxRatio(reflectance), objects ? objects.maxReflectance : 0), 0.9999);
  // First level per surface: blocks of block² texels, at most REDUCE_GRID² of them.
  const levels = layouts.map((l) => {
    const block = Math.max(1, Math.ceil(Math.max(l.width, l.height) / REDUCE_GRID));
    return { block, target: pool.acquire(Math.ceil(l.width / block), Math.ceil(l.height / block)) };
  });
  const stats = pool.acquire(Math.max(1, capacity), 1);
  const reduce = passProgram(gl, reduceSumPass);
  const ratio = passProgram(gl, fluxRatioPass);
  if (openings && !objects) throw new Error('flux statistics: a room with openings has its surfaces in the objects’ atlas');
  const areas = new Float32Array(layouts.map((l) => (openings ? 0 : texelArea(l))));
  const series = openings ? { row: pool.acquire(Math.max(1, capacity), 1), ratio: passProgram(gl, seriesRatioPass), reflected: passProgram(gl, objectReflectedFluxPass) } : null;
  const rho = new Float32Array(reflectance.flat());
  const sum = (s: number) => levels[s].target.texture;
  // The atlas: two weighted first levels (Σ E·c and Σ ρ·E·c).
  const objectLevels = objects
    ? (() => {
        const block = Math.max(1, Math.ceil(Math.max(objects.width, objects.height) / REDUCE_GRID));
        const size = [Math.ceil(objects.width / block), Math.ceil(objects.height / block)] as const;
        return { block, flux: pool.acquire(size[0], size[1]), reflected: pool.acquire(size[0], size[1]) };
      })()
    : null;
  const objectReduce = objects ? passProgram(gl, objectReduceSumPass) : null;
  const objectRatio = objects ? passProgram(gl, objectFluxRatioPass) : null;

  return {
    stats,
    record(index, maps, scale) {
      if (index < 0 || index >= capacity) throw new Error(`flux statistics: record ${index} outside 0..${capacity - 1}`);
      if (maps.length !== layouts.length + (objects ? 1 : 0)) throw new Error(`flux statistics: ${maps.length} maps for ${layouts.length} surfaces${objects ? ' and the atlas' : ''}`);
      layouts.forEach((_, s) => runPass(gl, reduce, levels[s].target, { uSource: maps[s].texture, uBlock: levels[s].block }));
      // The fused pass's uniforms for the six walls; the objects' variant adds the atlas's two sums.
      const walls = {
        uSum0: sum(0),
        uSum1: sum(1),
        uSum2: sum(2),
        uSum3: sum(3),
        uSum4: sum(4),
        uSum5: sum(5),
        uArea: areas.map((a) => a * scale),
        uRho: rho,
        uMaxRatio: maxRatio,
        uLuminance: LUMINANCE_WEIGHTS,
      };
      const texel = [index, 0, 1, 1] as const;
      if (objects && objectLevels && objectReduce && objectRatio) {
        const common = { uSource: maps[layouts.length].texture, uPoints: objects.points, uRho: objects.reflectance, uBlock: objectLevels.block };
        runPass(gl, objectReduce, objectLevels.flux, { ...common, uReflected: 0 });
        runPass(gl, objectReduce, objectLevels.reflected, { ...common, uReflected: 1 });
        const atlas = { uSum6: objectLevels.flux.texture, uSum7: objectLevels.reflected.texture, uObjectArea: objects.texelSize * objects.texelSize * scale };
        runPass(gl, objectRatio, stats, { ...walls, ...atlas }, texel);
        if (series) runPass(gl, series.reflected, series.row, { ...walls, ...atlas }, texel);
      } else runPass(gl, ratio, stats, walls, texel);
      // A room with openings: record k ≥ 1 is R_k / R_{k−1}, over the flux-weighted reflectance just written.
      if (series && index > 0) runPass(gl, series.ratio, stats, { uReflected: series.row.texture, uIndex: index, uMaxRatio: maxRatio }, texel);
    },
    read(count) {
      const rgba = readRgba(gl, stats);
      onRead(rgba.byteLength);
      return Array.from({ length: count }, (_, i) => ({
        ratio: [rgba[i * 4], rgba[i * 4 + 1], rgba[i * 4 + 2]] as Rgb,
        fluxY: rgba[i * 4 + 3],
      }));
    },
    dispose() {
      for (const t of [...levels.map((l) => l.target), stats, ...(series ? [series.row] : [])]) pool.release(t);
      if (objectLevels) for (const t of [objectLevels.flux, objectLevels.reflected]) pool.release(t);
    },
  };
}
