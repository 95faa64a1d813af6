import type { Rgb } from '../model/lightingScene';
import { fluxRatioFragment, reduceSumFragment, REDUCE_FACTOR } from '../../shaders/fluxReduce.glsl';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import { bindTexture, createFloatTarget, deleteTarget, getProgram, readRgba, type FloatTarget } from './glResources';
import { texelArea, type SurfaceLayout } from './surfaceLayout';

/** Per recorded map set: flux-weighted reflectance per channel and the photometric flux (lm). */
export interface FluxRecord {
  ratio: Rgb;
  fluxY: number;
}

/**
 * Flux statistics of the bounce maps, kept on the GPU (issue: no CPU–GPU
 * round trip inside a bake). `record(index, maps, scale)` reduces the six maps
 * to Σ E per surface (REDUCE_FACTOR² blocks per pass) and writes
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
  layouts: SurfaceLayout[],
  reflectance: Rgb[],
  capacity: number,
  onRead: (bytes: number) => void,
): FluxStatistics {
  const maxRatio = Math.min(Math.max(...reflectance.flat()), 0.9999);
  // Reduction chain per surface: w×h → ⌈w/4⌉×⌈h/4⌉ → … → 1×1 (at least one level).
  const chains: FloatTarget[][] = layouts.map((l) => {
    const chain: FloatTarget[] = [];
    let [w, h] = [l.width, l.height];
    do {
      w = Math.ceil(w / REDUCE_FACTOR);
      h = Math.ceil(h / REDUCE_FACTOR);
      chain.push(createFloatTarget(gl, w, h, false));
    } while (w > 1 || h > 1);
    return chain;
  });
  const stats = createFloatTarget(gl, Math.max(1, capacity), 1, false);
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
        let source = map;
        for (const level of chains[s]) {
          gl.bindFramebuffer(gl.FRAMEBUFFER, level.framebuffer);
          gl.viewport(0, 0, level.width, level.height);
          gl.useProgram(reduce);
          bindTexture(gl, reduce, 'uSource', 0, source.texture);
          gl.drawArrays(gl.TRIANGLES, 0, 3);
          source = level;
        }
      });
      drawTexel(stats, index, ratio, () => {
        chains.forEach((chain, s) => bindTexture(gl, ratio, `uSum${s}`, s, chain[chain.length - 1].texture));
        // Array uniforms by their first element's name: headless-gl 9 rc returns null for the bare name.
        gl.uniform1fv(gl.getUniformLocation(ratio, 'uArea[0]'), areas.map((a) => a * scale));
        gl.uniform3fv(gl.getUniformLocation(ratio, 'uRho[0]'), rho);
        gl.uniform1f(gl.getUniformLocation(ratio, 'uMaxRatio'), maxRatio);
        gl.uniform3fv(gl.getUniformLocation(ratio, 'uLuminance'), LUMINANCE_WEIGHTS);
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
      for (const t of [...chains.flat(), stats]) deleteTarget(gl, t);
    },
  };
}
