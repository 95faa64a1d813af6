import { fullscreenVertex } from '../../../shaders/fullscreen.glsl';

/**
 * Programs per context, keyed by fragment source: identical scenes never
 * recompile. An entry is pending while its compile and link may still run
 * (startPrograms): the driver is free to compile those in parallel (ANGLE
 * has a worker pool), and nothing waits until getProgram asks for the result.
 */
interface CacheEntry {
  program: WebGLProgram;
  pending: { vs: WebGLShader; fs: WebGLShader; source: string } | null;
}
const programCaches = new WeakMap<WebGL2RenderingContext, Map<string, CacheEntry>>();

export interface ProgramInfo {
  program: WebGLProgram;
  /** True when this call (or the startPrograms before it) compiled it; false: taken from the cache. */
  compiled: boolean;
}

function cacheOf(gl: WebGL2RenderingContext): Map<string, CacheEntry> {
  let cache = programCaches.get(gl);
  if (!cache) programCaches.set(gl, (cache = new Map()));
  return cache;
}

function shader(gl: WebGL2RenderingContext, type: number, source: string): WebGLShader {
  const s = gl.createShader(type);
  if (!s) throw new Error('WebGL: createShader failed (context lost?)');
  gl.shaderSource(s, source);
  gl.compileShader(s);
  return s;
}

/** Issue compile + link of a fragment shader without asking for the result (no wait). */
function begin(gl: WebGL2RenderingContext, fragmentSource: string): CacheEntry {
  const program = gl.createProgram();
  if (!program) throw new Error('WebGL: createProgram failed (context lost?)');
  const vs = shader(gl, gl.VERTEX_SHADER, fullscreenVertex);
  const fs = shader(gl, gl.FRAGMENT_SHADER, fragmentSource);
  gl.attachShader(program, vs);
  gl.attachShader(program, fs);
  gl.linkProgram(program);
  return { program, pending: { vs, fs, source: fragmentSource } };
}

/** Wait for a pending entry and turn a failure into an error with the numbered source. */
function settle(gl: WebGL2RenderingContext, entry: CacheEntry): void {
  const p = entry.pending;
  if (!p) return;
  entry.pending = null;
  const linked = gl.getProgramParameter(entry.program, gl.LINK_STATUS);
  try {
    if (!linked) {
      for (const s of [p.vs, p.fs]) {
        if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
          const numbered = (s === p.vs ? fullscreenVertex : p.source).split('\n').map((line, i) => `${i + 1}: ${line}`).join('\n');
          throw new Error(`GLSL compile error: ${gl.getShaderInfoLog(s) ?? ''}\n${numbered}`);
        }
      }
      throw new Error(`GLSL link error: ${gl.getProgramInfoLog(entry.program) ?? ''}`);
    }
  } finally {
    gl.deleteShader(p.vs);
    gl.deleteShader(p.fs);
  }
}

/**
 * Start compiling every program a bake will need before the first is used,
 * so the driver can compile them side by side instead of one after another
 * (measured: docs/benchmarks.md "GPU"). Already cached sources cost nothing.
 */
export function startPrograms(gl: WebGL2RenderingContext, fragmentSources: readonly string[]): void {
  const cache = cacheOf(gl);
  for (const source of fragmentSources) if (!cache.has(source)) cache.set(source, begin(gl, source));
}

/** The program for a fragment shader (with the shared full-screen vertex shader), cached by source. */
export function getProgram(gl: WebGL2RenderingContext, fragmentSource: string): ProgramInfo {
  const cache = cacheOf(gl);
  let entry = cache.get(fragmentSource);
  const compiled = !entry || entry.pending !== null;
  if (!entry) cache.set(fragmentSource, (entry = begin(gl, fragmentSource)));
  try {
    settle(gl, entry);
  } catch (error) {
    cache.delete(fragmentSource);
    gl.deleteProgram(entry.program);
    throw error;
  }
  return { program: entry.program, compiled };
}

/** Number of programs cached for this context (tests check reuse). */
export function cachedProgramCount(gl: WebGL2RenderingContext): number {
  return programCaches.get(gl)?.size ?? 0;
}

/** A float render target: texture + framebuffer, RGBA32F (no overflow: half floats stop at 65 504 lx). */
export interface FloatTarget {
  texture: WebGLTexture;
  framebuffer: WebGLFramebuffer;
  width: number;
  height: number;
}

export function requireFloatTargets(gl: WebGL2RenderingContext): { linear: boolean } {
  if (!gl.getExtension('EXT_color_buffer_float')) {
    throw new Error('WebGL2 without EXT_color_buffer_float: float light maps cannot be rendered on this device');
  }
  return { linear: !!gl.getExtension('OES_texture_float_linear') };
}

export function createFloatTarget(gl: WebGL2RenderingContext, width: number, height: number, linear: boolean): FloatTarget {
  const texture = gl.createTexture();
  const framebuffer = gl.createFramebuffer();
  if (!texture || !framebuffer) throw new Error('WebGL: out of resources creating a light map');
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, null);
  const filter = linear ? gl.LINEAR : gl.NEAREST;
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
  gl.bindFramebuffer(gl.FRAMEBUFFER, framebuffer);
  gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, texture, 0);
  const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
  if (status !== gl.FRAMEBUFFER_COMPLETE) throw new Error(`WebGL: RGBA32F framebuffer incomplete (0x${status.toString(16)})`);
  clearTarget(gl, { texture, framebuffer, width, height });
  return { texture, framebuffer, width, height };
}

export function clearTarget(gl: WebGL2RenderingContext, target: FloatTarget): void {
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  // headless-gl 9 aborts on a plain array here: pass a typed array.
  gl.clearBufferfv(gl.COLOR, 0, new Float32Array(4));
}

export function deleteTarget(gl: WebGL2RenderingContext, target: FloatTarget): void {
  gl.deleteFramebuffer(target.framebuffer);
  gl.deleteTexture(target.texture);
}

/** Float data texture (R32F profile tables, RGBA32F patch lists), read with texelFetch only. */
export function createDataTexture(gl: WebGL2RenderingContext, data: Float32Array, width: number, rows: number, channels: 1 | 4 = 1): WebGLTexture {
  const texture = gl.createTexture();
  if (!texture) throw new Error('WebGL: out of resources creating a data texture');
  gl.bindTexture(gl.TEXTURE_2D, texture);
  gl.pixelStorei(gl.UNPACK_ALIGNMENT, 1);
  if (channels === 4) gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, rows, 0, gl.RGBA, gl.FLOAT, data);
  else gl.texImage2D(gl.TEXTURE_2D, 0, gl.R32F, width, rows, 0, gl.RED, gl.FLOAT, data);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
  gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
  return texture;
}

/** Upload RGB float data (3 per texel, rows from v = 0) into a target. */
export function uploadRgb(gl: WebGL2RenderingContext, target: FloatTarget, rgb: Float32Array): void {
  const rgba = new Float32Array(target.width * target.height * 4);
  for (let i = 0; i < target.width * target.height; i++) {
    rgba[i * 4] = rgb[i * 3];
    rgba[i * 4 + 1] = rgb[i * 3 + 1];
    rgba[i * 4 + 2] = rgb[i * 3 + 2];
    rgba[i * 4 + 3] = 1;
  }
  gl.bindTexture(gl.TEXTURE_2D, target.texture);
  gl.texSubImage2D(gl.TEXTURE_2D, 0, 0, 0, target.width, target.height, gl.RGBA, gl.FLOAT, rgba);
}

/** Read a target back as RGBA floats (4 per texel), row j = 0 first: one readPixels, a full pipeline wait. */
export function readRgba(gl: WebGL2RenderingContext, target: FloatTarget): Float32Array {
  const rgba = new Float32Array(target.width * target.height * 4);
  gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
  gl.readPixels(0, 0, target.width, target.height, gl.RGBA, gl.FLOAT, rgba);
  return rgba;
}

/** Read a target back as RGB floats (3 per texel), row j = 0 first. */
export function readRgb(gl: WebGL2RenderingContext, target: FloatTarget): Float32Array {
  const rgba = readRgba(gl, target);
  const rgb = new Float32Array(target.width * target.height * 3);
  for (let i = 0; i < target.width * target.height; i++) {
    rgb[i * 3] = rgba[i * 4];
    rgb[i * 3 + 1] = rgba[i * 4 + 1];
    rgb[i * 3 + 2] = rgba[i * 4 + 2];
  }
  return rgb;
}

const locationCaches = new WeakMap<WebGLProgram, Map<string, WebGLUniformLocation | null>>();

/**
 * gl.getUniformLocation, remembered per program: a bake makes hundreds of
 * small draws and the lookup (a string crossing into the driver, and in
 * headless-gl through JS validation) is a measurable part of each.
 */
export function uniformLocation(gl: WebGL2RenderingContext, program: WebGLProgram, name: string): WebGLUniformLocation | null {
  let cache = locationCaches.get(program);
  if (!cache) locationCaches.set(program, (cache = new Map()));
  let loc = cache.get(name);
  if (loc === undefined) cache.set(name, (loc = gl.getUniformLocation(program, name)));
  return loc;
}
