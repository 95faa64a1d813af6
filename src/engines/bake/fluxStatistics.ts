import type { Rgb } from '../../core/model/lightingScene';
import { fluxRatioFragment, reduceSumFragment, REDUCE_GRID } from '../../../shaders/fluxReduce.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import { bindTexture, getProgram, readRgba, uniformLocation, type FloatTarget } from './glResources';
import type { TargetPool } from './targetPool';
import { texelArea, type SurfaceLayout } from './surfaceLayout';

/** Per recorded map set: flux-weighted reflectance per channel and the photometric flux (lm). */
export interface FluxRecord {
  ratio: Rgb;
  fluxY: number;
}

/**
 * Flux statistics of the bounce maps, kept on the GPU (issue: no CPU–GPU
 * round trip inside a bake). `record(index, maps, scale)` reduces the six maps
 * to at most REDUCE_GRID² partial sums per surface, and one fused pass adds
 * them up and writes
 * (r_R, r_G, r_B, Φ_Y) into texel `index` of a stats row; the tail combine
 * samples that row directly. `read()` fetches the whole row in one read-back
 * (report time only).
 */
export interface FluxStatistics {
  /** Row texture: texel i = record i (RGBA32F, width = capacity). */
  readonly stats: FloatTarget;
  record(index: number, maps: FloatTarget[], scale: number): void;
  /** Records 0..count−1, in one readPixels of `capacity` texels. */
  read(count: number): FluxRecord[];
  dispose(): void;
}

export function createFluxStatistics(
  gl: WebGL2RenderingContext,
  pool: TargetPool,
  layouts: SurfaceLayout[],
  reflectance: Rgb[],
  capacity: number,
  onRead: (bytes: number) => void,
): FluxStatistics {
  const maxRatio = Math.min(Math.max(...reflectance.flat()), 0.9999);
  // First level per surface: blocks of block² texels, at most REDUCE_GRID² of them.
  const levels = layouts.map((l) => {
    const block = Math.max(1, Math.ceil(Math.max(l.width, l.height) / REDUCE_GRID));
    return { block, target: pool.acquire(Math.ceil(l.width / block), Math.ceil(l.height / block)) };
  });
  const stats = pool.acquire(Math.max(1, capacity), 1);
  const reduce = getProgram(gl, reduceSumFragment).program;
  const ratio = getProgram(gl, fluxRatioFragment).program;
  const areas = new Float32Array(layouts.map(texelArea));
  const rho = new Float32Array(reflectance.flat());

  const drawTexel = (target: FloatTarget, x: number, program: WebGLProgram, bind: () => void) => {
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
    gl.viewport(x, 0, 1, 1);
    gl.useProgram(program);
    bind();
    gl.drawArrays(gl.TRIANGLES, 0, 3);
  };

  return {
    stats,
    record(index, maps, scale) {
      if (index < 0 || index >= capacity) throw new Error(`flux statistics: record ${index} outside 0..${capacity - 1}`);
      maps.forEach((map, s) => {
        const { block, target } = levels[s];
        gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
        gl.viewport(0, 0, target.width, target.height);
        gl.useProgram(reduce);
        bindTexture(gl, reduce, 'uSource', 0, map.texture);
        gl.uniform1i(uniformLocation(gl, reduce, 'uBlock'), block);
        gl.drawArrays(gl.TRIANGLES, 0, 3);
      });
      drawTexel(stats, index, ratio, () => {
        levels.forEach((level, s) => bindTexture(gl, ratio, `uSum${s}`, s, level.target.texture));
        // Array uniforms by their first element's name: headless-gl 9 rc returns null for the bare name.
        gl.uniform1fv(uniformLocation(gl, ratio, 'uArea[0]'), areas.map((a) => a * scale));
        gl.uniform3fv(uniformLocation(gl, ratio, 'uRho[0]'), rho);
        gl.uniform1f(uniformLocation(gl, ratio, 'uMaxRatio'), maxRatio);
        gl.uniform3fv(uniformLocation(gl, ratio, 'uLuminance'), LUMINANCE_WEIGHTS);
      });
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
      for (const t of [...levels.map((l) => l.target), stats]) pool.release(t);
    },
  };
}
