/**
 * One input of the mesh fuzz target: the files a user picks together (an .obj with its .mtl, a
 * .gltf with its .bin, a .glb) and the unit chosen, as one byte string so a failing input is kept
 * as one regression file: `units <u>\n` then per file `<name>\n<length>\n<bytes>`.
 */
import type { MeshFile } from '../../src/engines/meshImport/importedMesh';
import type { MeshUnitsOption } from '../../src/engines/meshImport/meshUnits';

export interface MeshBundle {
  units: MeshUnitsOption;
  files: MeshFile[];
}

const UNITS: readonly MeshUnitsOption[] = ['auto', 'm', 'cm', 'mm', 'in'];
const encoder = new TextEncoder();
const decoder = new TextDecoder();

export function encodeBundle(bundle: MeshBundle): Uint8Array {
  const parts: Uint8Array[] = [encoder.encode(`units ${bundle.units}\n`)];
  for (const f of bundle.files) parts.push(encoder.encode(`${f.name.replace(/\n/g, '_')}\n${f.bytes.length}\n`), f.bytes);
  const out = new Uint8Array(parts.reduce((n, p) => n + p.length, 0));
  let at = 0;
  for (const p of parts) {
    out.set(p, at);
    at += p.length;
  }
  return out;
}

/** The bundle, as far as it reads: a damaged header or length ends the file list there (the rest is the last file's bytes). */
export function decodeBundle(bytes: Uint8Array): MeshBundle {
  let at = 0;
  const line = (): string | null => {
    const end = bytes.indexOf(10, at);
    if (end < 0 || end - at > 4096) return null;
    const text = decoder.decode(bytes.subarray(at, end));
    at = end + 1;
    return text;
  };
  const head = line();
  const unit = head?.startsWith('units ') ? head.slice(6) : 'auto';
  const units = (UNITS as readonly string[]).includes(unit) ? (unit as MeshUnitsOption) : 'auto';
  const files: MeshFile[] = [];
  while (at < bytes.length && files.length < 8) {
    const name = line();
    const length = name === null ? null : Number(line());
    if (name === null || length === null || !Number.isInteger(length) || length < 0) break;
    files.push({ name: name || 'model.obj', bytes: bytes.slice(at, Math.min(bytes.length, at + length)) });
    at += length;
  }
  return { units, files: files.length > 0 ? files : [{ name: 'model.obj', bytes }] };
}
