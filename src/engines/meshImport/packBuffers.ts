import { excerpt, oneLine } from '../../core/untrustedJson';
import { findFile } from './findFile';
import type { MeshFile, MeshImportOptions } from './importedMesh';
import { shortName } from './readMtlMaterials';
import { MODEL_BYTE_CAPS } from './byteCaps';
import { formatCount } from './triangleBudget';
import type { GltfJson } from './gltfJson';
import { list, objectAt } from './gltfJson';

/** Every buffer's bytes in one BIN chunk (8-byte aligned), buffer views pointed at it. */
export async function packBuffers(json: GltfJson, glbBin: Uint8Array | undefined, files: readonly MeshFile[], options: MeshImportOptions, name: string, fail: (p: string) => never): Promise<Uint8Array> {
  const buffers = list(json, 'buffers', fail);
  const parts: Uint8Array[] = [];
  for (let i = 0; i < buffers.length; i++) {
    const b = objectAt(buffers, i, 'buffers', fail);
    const byteLength = b.byteLength;
    if (typeof byteLength !== 'number' || !Number.isInteger(byteLength) || byteLength < 0) fail(`buffers[${i}].byteLength must be a whole number of bytes`);
    const uri = b.uri;
    let bytes: Uint8Array | undefined;
    if (uri === undefined) {
      if (i !== 0 || !glbBin) fail(`buffers[${i}] has no uri and there is no GLB binary chunk for it`);
      bytes = glbBin;
    } else if (typeof uri !== 'string') {
      fail(`buffers[${i}].uri must be a string`);
    } else if (uri.startsWith('data:')) {
      bytes = decodeDataUri(uri, `buffers[${i}]`, fail);
    } else {
      bytes = findFile(files, uri)?.bytes;
      if (!bytes && options.readFile) {
        try {
          bytes = await options.readFile(uri);
        } catch (error) {
          fail(`buffers[${i}]: cannot read ${shortName(uri)} (${error instanceof Error ? oneLine(error.message, 60) : 'read error'})`);
        }
      }
      if (!bytes) fail(`buffers[${i}]: ${shortName(uri)} is missing (pick it together with ${name})`);
      if (bytes!.length > MODEL_BYTE_CAPS.glb) fail(`buffers[${i}]: ${shortName(uri)} has ${(bytes!.length / 1e6).toPrecision(3)} MB; at most ${MODEL_BYTE_CAPS.glb / 1e6} MB are read`);
    }
    if (bytes!.length < (byteLength as number)) {
      fail(`buffers[${i}]: ${formatCount(bytes!.length)} bytes, but byteLength says ${formatCount(byteLength as number)} (truncated?)`);
    }
    parts.push(bytes!.subarray(0, byteLength as number));
  }
  const offsets: number[] = [];
  let total = 0;
  for (const p of parts) {
    offsets.push(total);
    total += Math.ceil(p.length / 8) * 8;
  }
  // Each buffer is capped; together they are copied into one, which the same cap bounds.
  if (total > MODEL_BYTE_CAPS.glb) fail(`${parts.length} buffers of ${(total / 1e6).toPrecision(3)} MB together; at most ${MODEL_BYTE_CAPS.glb / 1e6} MB are read`);
  const binary = new Uint8Array(total);
  parts.forEach((p, i) => binary.set(p, offsets[i]));
  const views = list(json, 'bufferViews', fail);
  views.forEach((_, k) => {
    const v = objectAt(views, k, 'bufferViews', fail);
    const b = v.buffer;
    if (typeof b !== 'number' || !Number.isInteger(b) || b < 0 || b >= parts.length) fail(`bufferViews[${k}].buffer ${excerpt(b ?? null)} is not a buffer of this file`);
    const offset = v.byteOffset ?? 0;
    const length = v.byteLength;
    if (typeof offset !== 'number' || !Number.isInteger(offset) || offset < 0) fail(`bufferViews[${k}].byteOffset must be a whole number`);
    if (typeof length !== 'number' || !Number.isInteger(length) || length < 0) fail(`bufferViews[${k}].byteLength must be a whole number`);
    if ((offset as number) + (length as number) > parts[b as number].length) {
      fail(`bufferViews[${k}]: ${formatCount(length as number)} bytes from byte ${formatCount(offset as number)} reach beyond the ${formatCount(parts[b as number].length)} bytes of buffers[${b}]`);
    }
    v.buffer = 0;
    v.byteOffset = offsets[b as number] + (offset as number);
  });
  json.buffers = total > 0 ? [{ byteLength: total }] : [];
  return binary;
}

/** Bytes of a base64 data URI (glTF 2.0 §3.6.2.1 allows only base64 data URIs for buffers). */
function decodeDataUri(uri: string, where: string, fail: (p: string) => never): Uint8Array {
  if (uri.length > MODEL_BYTE_CAPS.dataUri) fail(`${where}: a data URI of ${(uri.length / 1e6).toPrecision(3)} MB; at most ${MODEL_BYTE_CAPS.dataUri / 1e6} MB are read`);
  const comma = uri.indexOf(',');
  if (comma < 0 || !/;base64$/i.test(uri.slice(0, comma))) fail(`${where}: a data URI must be base64`);
  const data = uri.slice(comma + 1).replace(/\s+/g, '');
  if (!/^[A-Za-z0-9+/]*={0,2}$/.test(data) || data.length % 4 === 1) fail(`${where}: the data URI is not valid base64`);
  const binary = atob(data.padEnd(Math.ceil(data.length / 4) * 4, '='));
  const out = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) out[i] = binary.charCodeAt(i);
  return out;
}
