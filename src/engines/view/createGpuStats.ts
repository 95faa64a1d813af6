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

/**
 * Which texels of a map count: a Uint8Array of one byte per texel, row 0 first, 1 where the texel is
 * left out (floorUnderObjects); a Float32Array of one weight per texel (a shaped floor's coverage in
 * the atlas, shapedFloorWeights.ts), 0 where left out; null: every texel, weight 1.
 */
export type StatsMask = Uint8Array | Float32Array | null;

export interface GpuStats {
  /**
   * Reduce `map` (RGB lux in an RGBA float texture) over the texels `mask` counts to Ē (weighted by
   * the mask's weights), Emin, Emax, U0; `points` is the texels counted (Σ of the weights).
   */
  request(map: FloatTarget, mask: StatsMask): PendingStats;
  /** Read-backs of the 16-byte statistics texels (never a map). */
  readonly readbacks: ReadbackCounter;
  dispose(): void;
}

/** The mask's weights, one float per texel's red channel (createGpuStats's mask texture). */
function maskRgba(width: number, height: number, mask: StatsMask): Float32Array {
  const rgba = new Float32Array(width * height * 4);
  for (let i = 0; i < width * height; i++) rgba[i * 4] = mask === null ? 1 : mask instanceof Float32Array ? mask[i] : mask[i] ? 0 : 1;
  return rgba;
}

/** A PIXEL_PACK buffer of 8 statistics texels, or null where the context has none (headless-gl 9). */
function createPackBuffer(gl: WebGL2RenderingContext): WebGLBuffer | null {
  const buffer = gl.createBuffer();
  gl.getError();
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, buffer);
  const supported = gl.getError() === gl.NO_ERROR;
  if (supported) gl.bufferData(gl.PIXEL_PACK_BUFFER, 16 * 8, gl.STREAM_READ);
  gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  if (!supported) gl.deleteBuffer(buffer);
  return supported ? buffer : null;
}

function toStats([sum, weight, min, max]: Float32Array): IlluminanceStats {
  if (!(weight > 0)) return { avg: 0, min: 0, max: 0, u0: 0, points: 0 };
  const avg = sum / weight;
  return { avg, min, max, u0: avg > 0 ? min / avg : 0, points: Math.round(weight) };
}

/** The state one statistics context keeps: programs, the partials, the masks by size, the pack buffer. */
interface StatsState {
  gl: WebGL2RenderingContext;
  block: ReturnType<typeof passProgram<typeof statsBlockPass.uniforms>>;
  merge: ReturnType<typeof passProgram<typeof statsMergePass.uniforms>>;
  partials: FloatTarget;
  masks: Map<string, { mask: StatsMask; target: FloatTarget }>;
  pbo: WebGLBuffer | null;
  slot: number;
  readbacks: ReadbackCounter;
}

/** The mask's texture for a map of this size (uploaded again only when another mask is asked for). */
function maskTarget(st: StatsState, width: number, height: number, mask: StatsMask): FloatTarget {
  const key = `${width}x${height}`;
  const known = st.masks.get(key);
  if (known && known.mask === mask) return known.target;
  const target = known?.target ?? createFloatTarget(st.gl, width, height, false);
  st.gl.bindTexture(st.gl.TEXTURE_2D, target.texture);
  st.gl.texSubImage2D(st.gl.TEXTURE_2D, 0, 0, 0, width, height, st.gl.RGBA, st.gl.FLOAT, maskRgba(width, height, mask));
  st.masks.set(key, { mask, target });
  return target;
}

/** Reduce the map to one texel, copy it into the pack buffer (where there is one) and fence it. */
function reduce(st: StatsState, map: FloatTarget, mask: StatsMask): { result: FloatTarget; offset: number; fence: WebGLSync | null } {
  const { gl } = st;
  const size = Math.ceil(Math.max(map.width, map.height) / STATS_GRID);
  const grid: [number, number] = [Math.ceil(map.width / size), Math.ceil(map.height / size)];
  gl.bindFramebuffer(gl.FRAMEBUFFER, st.partials.framebuffer);
  gl.clearBufferfv(gl.COLOR, 0, new Float32Array([0, 0, 3e38, -3e38]));
  runPass(gl, st.block, st.partials, { uSource: map.texture, uMask: maskTarget(st, map.width, map.height, mask).texture, uBlock: size, uLuminance: LUMINANCE_WEIGHTS }, [0, 0, grid[0], grid[1]]);
  // The merge reads the whole partials texture: the unused texels were cleared to the neutral (0, 0, big, −big).
  const result = createFloatTarget(gl, 1, 1, false);
  runPass(gl, st.merge, result, { uSource: st.partials.texture });
  const offset = (st.slot++ % 8) * 16;
  if (st.pbo) {
    gl.bindFramebuffer(gl.FRAMEBUFFER, result.framebuffer);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, st.pbo);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, offset);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  }
  const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
  gl.flush();
  return { result, offset, fence };
}

/** The request's texel once its fence has signalled (never waits), else null. */
function readWhenDone(st: StatsState, { result, offset, fence }: ReturnType<typeof reduce>): Float32Array | null {
  const { gl } = st;
  if (!fence) throw new Error('GPU statistics: fenceSync failed (context lost?)');
  const status = gl.clientWaitSync(fence, 0, 0);
  if (status !== gl.ALREADY_SIGNALED && status !== gl.CONDITION_SATISFIED) return null;
  gl.deleteSync(fence);
  const texel = new Float32Array(4);
  if (st.pbo) {
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, st.pbo);
    gl.getBufferSubData(gl.PIXEL_PACK_BUFFER, offset, texel);
    gl.bindBuffer(gl.PIXEL_PACK_BUFFER, null);
  } else {
    gl.bindFramebuffer(gl.FRAMEBUFFER, result.framebuffer);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.FLOAT, texel);
  }
  st.readbacks.count++;
  st.readbacks.bytes += 16;
  deleteTarget(gl, result);
  return texel;
}

/**
 * Ē, Emin, Emax, U0 of a map without reading the map back (docs/viewer.md, "Statistics on the GPU"):
 * statsReduce.glsl.ts reduces it to one texel (Σ w·Y, Σ w, Ymin, Ymax), which is copied into a
 * PIXEL_PACK buffer and fenced; `poll` reads the 16 bytes once the fence has signalled
 * (getBufferSubData), so no animation frame waits for the GPU. Where the context has no pixel-pack
 * buffers (headless-gl 9), the texel is read with readPixels after the fence signalled: the work is
 * done by then, and one texel crosses.
 */
export function createGpuStats(gl: WebGL2RenderingContext): GpuStats {
  requireFloatTargets(gl);
  const st: StatsState = {
    gl,
    block: passProgram(gl, statsBlockPass),
    merge: passProgram(gl, statsMergePass),
    partials: createFloatTarget(gl, STATS_GRID, STATS_GRID, false),
    masks: new Map(),
    pbo: createPackBuffer(gl),
    slot: 0,
    readbacks: { count: 0, bytes: 0 },
  };
  return {
    request(map, mask) {
      if (mask && mask.length !== map.width * map.height) throw new Error(`GPU statistics: the mask has ${mask.length} texels, the map ${map.width * map.height}`);
      const request = reduce(st, map, mask);
      let done: IlluminanceStats | null = null;
      return {
        poll() {
          if (done) return done;
          const texel = readWhenDone(st, request);
          return texel ? (done = toStats(texel)) : null;
        },
      };
    },
    readbacks: st.readbacks,
    dispose() {
      deleteTarget(gl, st.partials);
      for (const m of st.masks.values()) deleteTarget(gl, m.target);
      st.masks.clear();
      if (st.pbo) gl.deleteBuffer(st.pbo);
    },
  };
}
