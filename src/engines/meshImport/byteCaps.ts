import { InputError } from '../../core/inputError';

/**
 * Largest inputs the importer decodes, bytes, checked before any decoding (issue 32: 9–36 MB OBJ
 * files took 2–4.5 s before the vertex cap refused them). Each is several times what a model
 * within the triangle budget (MAX_IMPORT_TRIANGLES, about 48 000) needs even when written
 * wastefully: such an OBJ with normals and texture coordinates and no shared vertices is about
 * 14 MB, its glTF geometry under 10 MB. Documented in docs/scene-format.md, "Importing meshes".
 */
export const MODEL_BYTE_CAPS = {
  /** An .obj file. */
  obj: 24e6,
  /** An .mtl material library (a few kB in practice). */
  mtl: 4e6,
  /** A .gltf file's JSON, or a GLB's JSON chunk (data-URI buffers inside it included). */
  gltfJson: 24e6,
  /** A .glb file, or an external .bin buffer (embedded textures make GLBs larger than their geometry). */
  glb: 64e6,
  /** One base64 data URI, in characters of text. */
  dataUri: 24e6,
} as const;

/** Refuse `size` bytes of `what` in `file` above `cap`, with both numbers. */
export function checkByteCap(file: string, size: number, cap: number, what: string): void {
  if (size > cap) throw new InputError(`${file}: ${what} of ${mb(size)} MB; at most ${mb(cap)} MB are read`);
}

function mb(bytes: number): string {
  return String(Number((bytes / 1e6).toPrecision(3)));
}
