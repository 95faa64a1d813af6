import { createFloatTarget, deleteTarget, type FloatTarget } from '../../bake/floatTarget';
import { halfBits } from '../halfFloat';
import type { GpuRelightState, ReceiverTargets } from './gpuRelightState';

/** Half floats hold ±65 504 (IEEE 754 binary16): larger lux values would overflow, so such a map stays RGBA32F. */
const HALF_MAX = 65504;

/** An RGB map as RGBA texels: half floats where the precision asks for them and the values fit, else 32-bit floats. */
function rgbaTexels(data: Float32Array, width: number, height: number, half: boolean): Uint16Array | Float32Array {
  const rgba = half ? new Uint16Array(width * height * 4) : new Float32Array(width * height * 4);
  const convert = half ? halfBits : (v: number) => v;
  for (let i = 0, j = 0; i < data.length; i += 3, j += 4) {
    rgba[j] = convert(data[i]);
    rgba[j + 1] = convert(data[i + 1]);
    rgba[j + 2] = convert(data[i + 2]);
    rgba[j + 3] = convert(1);
  }
  return rgba;
}

/** The texture of a basis or indirect map, uploaded on first use (`float`: RGBA32F whatever the precision). */
export function uploadMap(s: GpuRelightState, data: Float32Array, width: number, height: number, float = false): WebGLTexture {
  const known = s.uploads.get(data);
  if (known) return known.texture;
  if (data.length !== width * height * 3) throw new Error(`GPU relight: a map has ${data.length / 3} texels, its receiver ${width * height}`);
  let peak = 0;
  for (let i = 0; i < data.length; i++) peak = Math.max(peak, Math.abs(data[i]));
  const half = !float && s.precision === 'half' && peak <= HALF_MAX;
  const rgba = rgbaTexels(data, width, height, half);
  const gl = s.gl;
  const texture = gl.createTexture();
  if (!texture) throw new Error('WebGL: out of resources creating a relight basis');
  gl.bindTexture(gl.TEXTURE_2D, texture);
  if (half) gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA16F, width, height, 0, gl.RGBA, gl.HALF_FLOAT, rgba);
  else gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, rgba);
  for (const p of [gl.TEXTURE_MIN_FILTER, gl.TEXTURE_MAG_FILTER]) gl.texParameteri(gl.TEXTURE_2D, p, gl.NEAREST);
  s.uploads.set(data, { texture, bytes: width * height * (half ? 8 : 16) });
  s.uploaded.count++;
  s.uploaded.bytes += rgba.byteLength;
  return texture;
}

/** The display targets of one receiver, made again when its size changed. */
export function receiverTargets(s: GpuRelightState, key: string, width: number, height: number): ReceiverTargets {
  let o = s.outputs.get(key);
  if (o && (o.direct.width !== width || o.direct.height !== height)) {
    for (const t of [o.direct, o.total, o.scratch]) deleteTarget(s.gl, t);
    o = undefined;
  }
  if (!o) s.outputs.set(key, (o = { direct: createFloatTarget(s.gl, width, height, s.linear), total: createFloatTarget(s.gl, width, height, s.linear), scratch: createFloatTarget(s.gl, width, height, false) }));
  return o;
}

/** A cleared texture of this size: the accumulator a direct map starts from. */
export function zeroOf(s: GpuRelightState, width: number, height: number): FloatTarget {
  const key = `${width}x${height}`;
  let z = s.zeros.get(key);
  if (!z) s.zeros.set(key, (z = createFloatTarget(s.gl, width, height, false)));
  return z;
}

/** Textures of maps no longer in use (a dropped basis, a replaced preview) are freed; the grid's stay. */
export function pruneUploads(s: GpuRelightState, inUse: Set<Float32Array>): void {
  for (const [data, u] of s.uploads) {
    if (inUse.has(data) || s.gridInUse.has(data)) continue;
    s.gl.deleteTexture(u.texture);
    s.uploads.delete(data);
  }
}

/** The grid relight's maps become these; the previous grid's that no longer take part are freed. */
export function replaceGridMaps(s: GpuRelightState, maps: Set<Float32Array>): void {
  const previous = s.gridInUse;
  s.gridInUse = maps;
  for (const data of previous) {
    const u = s.uploads.get(data);
    if (maps.has(data) || !u) continue;
    s.gl.deleteTexture(u.texture);
    s.uploads.delete(data);
  }
}

/** Bytes of GPU texture memory held now: uploads at their precision, display and zero targets at 16 B/texel. */
export function textureBytes(s: GpuRelightState): number {
  let bytes = 0;
  for (const u of s.uploads.values()) bytes += u.bytes;
  for (const o of s.outputs.values()) bytes += 3 * o.direct.width * o.direct.height * 16;
  for (const z of s.zeros.values()) bytes += z.width * z.height * 16;
  return bytes;
}

/** Frees every texture and target. */
export function disposeRelightTextures(s: GpuRelightState): void {
  s.gridInUse = new Set();
  pruneUploads(s, new Set());
  for (const o of s.outputs.values()) for (const t of [o.direct, o.total, o.scratch]) deleteTarget(s.gl, t);
  s.outputs.clear();
  for (const z of s.zeros.values()) deleteTarget(s.gl, z);
  s.zeros.clear();
  deleteTarget(s.gl, s.zero);
}
