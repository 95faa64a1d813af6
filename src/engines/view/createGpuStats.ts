import { STATS_GRID, statsBlockPass, statsMergePass } from '../../../shaders/statsReduce.glsl';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { createFloatTarget, deleteTarget, requireFloatTargets, type FloatTarget } from '../bake/floatTarget';
import { passProgram, runPass } from '../bake/runPass';
import type { ReadbackCounter } from '../relight/createGpuRelight';
import type { IlluminanceStats } from './lightStats';

/** A statistics request on its way: poll until the GPU has finished it. */
export interface PendingStats {
  /** The statistics once the GPU signalled the request's fence (never waits), else null. */
  poll(): IlluminanceStats | null;
}

export interface GpuStats {
  /**
   * Reduce `map` (RGB lux in an RGBA float texture) over the texels where `covered` is 0 (one byte per
   * texel, row 0 first: floorUnderObjects) to Ē, Emin, Emax, U0; null `covered` takes every texel.
   */
  request(map: FloatTarget, covered: Uint8Array | null): PendingStats;
  /** Read-backs of the 16-byte statistics texels (never a map). */
  readonly readbacks: ReadbackCounter;
  dispose(): void;
}

/**
 * Ē, Emin, Emax, U0 of a map without reading the map back (docs/viewer.md, "Statistics on the GPU"):
 * statsReduce.glsl.ts reduces it to one texel (ΣY, count, Ymin, Ymax), which is copied into a
 * PIXEL_PACK buffer and fenced; `poll` reads the 16 bytes once the fence has signalled
 * (getBufferSubData), so no animation frame waits for the GPU. Where the context has no pixel-pack
 * buffers (headless-gl 9), the texel is read with readPixels after the fence signalled: the work is
 * done by then, and one texel crosses.
 */
export function createGpuStats(gl: WebGL2RenderingContext): GpuStats {
  requireFloatTargets(gl);
  const block = passProgram(gl, statsBlockPass);
  const merge = passProgram(gl, statsMergePass);
  const partials = createFloatTarget(gl, STATS_GRID, STATS_GRID, false);
  const readbacks: ReadbackCounter = { count: 0, bytes: 0 };
  const masks = new Map<string, { covered: Uint8Array | null; target: FloatTarget }>();
  const pbo = (() => {
    const buffer = gl.createBuffer();
    gl.getError();
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, buffer);
    const supported = gl.getError() === gl.NO_ERROR;
    if (supported) gl.bufferData(gl.PIXEL_PACK_BUFFER, 16 * 8, gl.STREAM_READ);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
    if (!supported) gl.deleteBuffer(buffer);
    return supported ? buffer : null;
  })();
  let slot = 0;

  const maskOf = (width: number, height: number, covered: Uint8Array | null): FloatTarget => {
    const key = `${width}x${height}`;
    const known = masks.get(key);
    if (known && known.covered === covered) return known.target;
    const target = known?.target ?? createFloatTarget(gl, width, height, false);
    const rgba = new Float32Array(width * height * 4);
    for (let i = 0; i < width * height; i++) rgba[i * 4] = covered && covered[i] ? 0 : 1;
    gl.bindTexture(gl.TEXTURE_2D, target.texture);
    gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, width, height, gl.RGBA, gl.FLOAT, rgba);
    masks.set(key, { covered, target });
    return target;
  };

  const toStats = ([sum, count, min, max]: Float32Array): IlluminanceStats => {
    if (count === 0) return { avg: 0, min: 0, max: 0, u0: 0, points: 0 };
    const avg = sum / count;
    return { avg, min, max, u0: avg > 0 ? min / avg : 0, points: Math.round(count) };
  };

  return {
    request(map, covered) {
      if (covered && covered.length !== map.width * map.height) throw new Error(`GPU statistics: the mask has ${covered.length} texels, the map ${map.width * map.height}`);
      const size = Math.ceil(Math.max(map.width, map.height) / STATS_GRID);
      const grid: [number, number] = [Math.ceil(map.width / size), Math.ceil(map.height / size)];
      clearPartials();
      runPass(gl, block, partials, { uSource: map.texture, uMask: maskOf(map.width, map.height, covered).texture, uBlock: size, uLuminance: LUMINANCE_WEIGHTS }, [0, 0, grid[0], grid[1]]);
      // The merge reads the whole partials texture: the unused texels were cleared to the neutral (0, 0, big, −big).
      const result = createFloatTarget(gl, 1, 1, false);
      runPass(gl, merge, result, { uSource: partials.texture });
      const offset = (slot++ % 8) * 16;
      if (pbo) {
        gl.bindFramebuffer(gl.FRAMEBUFFER, result.framebuffer);
        gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pbo);
        gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, offset);
        gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
      }
      const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
      let done: IlluminanceStats | null = null;
      return {
        poll() {
          if (done) return done;
          if (!fence) throw new Error('GPU statistics: fenceSync failed (context lost?)');
          const status = gl.clientWaitSync(fence, 0, 0);
          if (status !== gl.ALREADY_SIGNALED && status !== gl.CONDITION_SATISFIED) return null;
          gl.deleteSync(fence);
          const texel = new Float32Array(4);
          if (pbo) {
            gl.bindBuffer(gl.PIXEL_PACK_BUFFER, pbo);
            gl.getBufferSubData(gl.PIXEL_PACK_BUFFER, offset, texel);
            gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
          } else {
            gl.bindFramebuffer(gl.FRAMEBUFFER, result.framebuffer);
            gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, texel);
          }
          readbacks.count++;
          readbacks.bytes += 16;
          deleteTarget(gl, result);
          return (done = toStats(texel));
        },
      };
    },
    readbacks,
    dispose() {
      deleteTarget(gl, partials);
      for (const m of masks.values()) deleteTarget(gl, m.target);
      masks.clear();
      if (pbo) gl.deleteBuffer(pbo);
    },
  };

  function clearPartials() {
    gl.bindFramebuffer(gl.FRAMEBUFFER, partials.framebuffer);
    gl.clearBufferfv(gl.COLOR, 0, new Float32Array([0, 0, 3e38, -3e38]));
  }
}
