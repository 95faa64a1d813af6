import { GLB_MAGIC, CHUNK_JSON, CHUNK_BIN } from './readGlb';

/** A GLB container (§4.4) holding `jsonText` and `binary`. */
export function buildGlb(jsonText: string, binary: Uint8Array): ArrayBuffer {
  const jsonBytes = new TextEncoder().encode(jsonText);
  const jsonLength = Math.ceil(jsonBytes.length / 4) * 4;
  const binLength = Math.ceil(binary.length / 4) * 4;
  const total = 12 + 8 + jsonLength + (binary.length > 0 ? 8 + binLength : 0);
  const out = new Uint8Array(total);
  const view = new DataView(out.buffer);
  view.setUint32(0, GLB_MAGIC, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, CHUNK_JSON, true);
  out.set(jsonBytes, 20);
  // JSON chunk padding is spaces (§4.4.3.2).
  out.fill(0x20, 20 + jsonBytes.length, 20 + jsonLength);
  if (binary.length > 0) {
    const at = 20 + jsonLength;
    view.setUint32(at, binLength, true);
    view.setUint32(at + 4, CHUNK_BIN, true);
    out.set(binary, at + 8);
  }
  return out.buffer;
}
