/**
 * A TriangleMesh in a JSON file: each typed array as base64 (RFC 4648 §4) of its bytes,
 * little-endian, so a Float32 vertex reads back bit for bit and a 10 000-triangle mesh costs
 * about 270 kB of text instead of a JSON number list several times longer (and past the readers'
 * 20 000-entry array limit). Used by scene files (version 3, sceneFile.ts).
 */
import type { MeshMaterial, TriangleMesh } from '../../mesh/triangleMesh';

export interface EncodedMesh {
  /** Float32 x, y, z per vertex, little-endian, base64. */
  readonly positions: string;
  /** Uint32 three per triangle, little-endian, base64. */
  readonly indices: string;
  /** Uint16 per triangle, little-endian, base64. */
  readonly materialOfTriangle: string;
  readonly materials: readonly MeshMaterial[];
}

type Kind = 'f32' | 'u32' | 'u16';
const SIZE: Record<Kind, number> = { f32: 4, u32: 4, u16: 2 };

function toBase64(bytes: Uint8Array): string {
  let bin = '';
  // Chunks keep String.fromCharCode's argument list short.
  for (let i = 0; i < bytes.length; i += 0x8000) bin += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(bin);
}

function encodeArray(values: ArrayLike<number>, kind: Kind): string {
  const bytes = new Uint8Array(values.length * SIZE[kind]);
  const view = new DataView(bytes.buffer);
  for (let i = 0; i < values.length; i++) {
    if (kind === 'f32') view.setFloat32(i * 4, values[i], true);
    else if (kind === 'u32') view.setUint32(i * 4, values[i], true);
    else view.setUint16(i * 2, values[i], true);
  }
  return toBase64(bytes);
}

/** Decodes one array; returns a message (not an exception) for bad text so the caller can name the field. */
function decodeArray(text: string, kind: Kind): Float32Array | Uint32Array | Uint16Array | string {
  if (!/^[A-Za-z0-9+/]*={0,2}$/.test(text) || text.length % 4 !== 0) return 'is not base64 (RFC 4648: A-Z a-z 0-9 + /, padded with =)';
  const bin = atob(text);
  if (bin.length % SIZE[kind] !== 0) return `holds ${bin.length} bytes, not a whole number of ${SIZE[kind]}-byte values`;
  const view = new DataView(Uint8Array.from(bin, (c) => c.charCodeAt(0)).buffer);
  const n = bin.length / SIZE[kind];
  const out = kind === 'f32' ? new Float32Array(n) : kind === 'u32' ? new Uint32Array(n) : new Uint16Array(n);
  for (let i = 0; i < n; i++) out[i] = kind === 'f32' ? view.getFloat32(i * 4, true) : kind === 'u32' ? view.getUint32(i * 4, true) : view.getUint16(i * 2, true);
  return out;
}

export function encodeMesh(mesh: TriangleMesh): EncodedMesh {
  return {
    positions: encodeArray(mesh.positions, 'f32'),
    indices: encodeArray(mesh.indices, 'u32'),
    materialOfTriangle: encodeArray(mesh.materialOfTriangle, 'u16'),
    materials: mesh.materials.map((m) => ({ name: m.name, reflectance: [m.reflectance[0], m.reflectance[1], m.reflectance[2]] })),
  };
}

/** The mesh, or `{ field, problem }` naming the first array that does not decode. Contents (ranges) are validate()'s (meshDataProblem). */
export function decodeMesh(encoded: EncodedMesh): TriangleMesh | { field: string; problem: string } {
  const positions = decodeArray(encoded.positions, 'f32');
  if (typeof positions === 'string') return { field: 'positions', problem: positions };
  const indices = decodeArray(encoded.indices, 'u32');
  if (typeof indices === 'string') return { field: 'indices', problem: indices };
  const materialOfTriangle = decodeArray(encoded.materialOfTriangle, 'u16');
  if (typeof materialOfTriangle === 'string') return { field: 'materialOfTriangle', problem: materialOfTriangle };
  return {
    positions: positions as Float32Array,
    indices: indices as Uint32Array,
    materialOfTriangle: materialOfTriangle as Uint16Array,
    materials: encoded.materials.map((m) => ({ name: m.name, reflectance: [m.reflectance[0], m.reflectance[1], m.reflectance[2]] })),
  };
}
