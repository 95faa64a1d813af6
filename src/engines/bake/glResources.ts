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
          const log = (gl.getShaderInfoLog(s) ?? '').trim();
          throw new Error(`GLSL compile error (${s === p.vs ? 'vertex' : 'fragment'}): ${log}\n${compileErrorExcerpt(s === p.vs ? fullscreenVertex : p.source, log)}`);
        }
      }
      throw new Error(`GLSL link error: ${gl.getProgramInfoLog(entry.program) ?? ''}`);
    }
  } finally {
    gl.deleteShader(p.vs);
    gl.deleteShader(p.fs);
  }
}

/** The window round the first line a compile log names, as three.js's WebGLProgram.js `handleSource`: lines e − 5 … e + 6. */
export const ERROR_CONTEXT_LINES = 6;

/**
 * The few source lines around the first error a compile log names (`ERROR: 0:<line>`, the form ANGLE
 * and the desktop drivers print), numbered from 1 and the error line marked with `>`, as three.js
 * prints them (src/renderers/webgl/WebGLProgram.js, handleSource): a generated bake shader runs to
 * hundreds of lines, and the whole numbered source buried the message. A log without a line number
 * gets the first 2·ERROR_CONTEXT_LINES lines.
 */
export function compileErrorExcerpt(source: string, log: string): string {
  const lines = source.split('\n');
  const match = /ERROR: \d+:(\d+)/.exec(log);
  const errorLine = match ? Number(match[1]) : 0;
  const from = Math.max(errorLine - ERROR_CONTEXT_LINES, 0);
  const to = Math.min(match ? errorLine + ERROR_CONTEXT_LINES : 2 * ERROR_CONTEXT_LINES, lines.length);
  const shown: string[] = [];
  for (let i = from; i < to; i++) shown.push(`${i + 1 === errorLine ? '>' : ' '} ${i + 1}: ${lines[i]}`);
  return shown.join('\n');
}

/** KHR_parallel_shader_compile's query (https://registry.khronos.org/webgl/extensions/KHR_parallel_shader_compile/). */
export const COMPLETION_STATUS_KHR = 0x91b1;

/**
 * Whether the programs of these fragment sources can be used without waiting: every one cached and
 * linked, or still compiling but reported complete by KHR_parallel_shader_compile's
 * COMPLETION_STATUS_KHR (polled as three.js's WebGLProgram.isReady does). Without the extension a
 * driver has no way to say, and the answer is true (the first use waits, as before). A caller that
 * started the compiles (startPrograms) polls this from its slices and draws only once it is true,
 * so the page keeps answering while the driver compiles. A source never started counts as not ready.
 */
export function programsReady(gl: WebGL2RenderingContext, fragmentSources: readonly string[]): boolean {
  const cache = cacheOf(gl);
  const parallel = gl.getExtension('KHR_parallel_shader_compile') !== null;
  for (const source of fragmentSources) {
    const entry = cache.get(source);
    if (!entry) return false;
    if (entry.pending && parallel && gl.getProgramParameter(entry.program, COMPLETION_STATUS_KHR) !== true) return false;
  }
  return true;
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
