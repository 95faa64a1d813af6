import { decodeText } from './decodeText';
import { MODEL_BYTE_CAPS } from './byteCaps';
import { formatCount } from './triangleBudget';

/** glTF 2.0 §4.4 "Binary glTF Layout": header magic "glTF", chunk types "JSON" and "BIN\0". */
export const GLB_MAGIC = 0x46546c67;
export const CHUNK_JSON = 0x4e4f534a;
export const CHUNK_BIN = 0x004e4942;

/** A little-endian uint32 at `offset`. */
export function readU32(bytes: Uint8Array, offset: number): number {
  return new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(offset, true);
}

/** The JSON text and BIN chunk of a GLB, every length checked against the file. */
export function readGlb(bytes: Uint8Array, fail: (p: string) => never): { text: string; bin: Uint8Array | undefined } {
  if (bytes.length < 20) fail(`truncated: ${bytes.length} bytes is too short for a GLB`);
  const version = readU32(bytes, 4);
  if (version !== 2) fail(`GLB container version ${version} (luxbox reads glTF 2.0)`);
  const length = readU32(bytes, 8);
  if (length > bytes.length) fail(`truncated: the header says ${formatCount(length)} bytes, the file has ${formatCount(bytes.length)}`);
  if (length < bytes.length) fail(`wrong length: the header says ${formatCount(length)} bytes, the file has ${formatCount(bytes.length)}`);
  let offset = 12;
  let text: string | undefined;
  let bin: Uint8Array | undefined;
  while (offset < length) {
    if (offset + 8 > length) fail(`truncated chunk header at byte ${offset}`);
    const chunkLength = readU32(bytes, offset);
    const type = readU32(bytes, offset + 4);
    const start = offset + 8;
    if (start + chunkLength > length) fail(`chunk at byte ${offset} (${formatCount(chunkLength)} bytes) runs past the end of the file`);
    const data = bytes.subarray(start, start + chunkLength);
    if (text === undefined) {
      if (type !== CHUNK_JSON) fail('the first chunk is not JSON');
      if (chunkLength > MODEL_BYTE_CAPS.gltfJson) fail(`a JSON chunk of ${(chunkLength / 1e6).toPrecision(3)} MB; at most ${MODEL_BYTE_CAPS.gltfJson / 1e6} MB are read`);
      text = decodeText(data);
    } else if (type === CHUNK_BIN && bin === undefined) {
      bin = data;
    }
    // Chunks start on 4-byte boundaries (§4.4.3.1); unknown chunk types are skipped.
    offset = start + Math.ceil(chunkLength / 4) * 4;
  }
  if (text === undefined) fail('no JSON chunk');
  return { text: text!, bin };
}
