/**
 * Mutators of the mesh fuzz target (issue 32), seeded and written for 3D models: byte flips,
 * truncation and splices on any file; for glTF (a .gltf's JSON or a GLB's JSON chunk, the GLB
 * rebuilt around it) field mutations aimed at the readers' arithmetic — negative, huge and
 * fractional offsets, strides and counts, huge arrays, many scenes, long names, huge coordinates
 * in node transforms, sparse accessors, wrong types; for OBJ/MTL huge coordinates, indices out of
 * range, long material names, continuations, NUL bytes and runs of thousands of lines.
 */
import { MODEL_BYTE_CAPS } from '../../src/engines/meshImport/byteCaps';
import type { Rng } from './mutate';
import type { MeshBundle } from './meshBundle';

type Json = Record<string, unknown>;
const encoder = new TextEncoder();
const decoder = new TextDecoder();

const HOSTILE_NUMBERS = [-4, -1, 0, 1, 2, 3, 3.5, 13, 252, 256, 65535, 2 ** 31, 2 ** 32 + 4, 1e9, 1e20, 1e308, -1e308, 0.1];
const HUGE_COORDINATES = ['3.4e38', '-3.4e38', '1e308', '1e39', '123456789', '1e-45', '99.99', '100.01', '-0'];

const pickNumber = (rng: Rng): number => (rng.chance(0.7) ? rng.pick(HOSTILE_NUMBERS) : rng.int(1 << rng.int(31)));
const longName = (rng: Rng): string => rng.pick(['x', 'ä', '😀', 'a\u0000b', '\\', '"', 'n ']).repeat(rng.pick([199, 200, 201, 300, 5000]));

/** Files of the bundle by kind. */
function mainFile(bundle: MeshBundle, pattern: RegExp) {
  return bundle.files.find((f) => pattern.test(f.name));
}

/** A random object reached from `json`'s top-level arrays (accessors[3], bufferViews[0] …), with its path. */
function randomEntry(json: Json, rng: Rng, keys: readonly string[]): [Json, string] | null {
  const key = rng.pick(keys);
  const list = json[key];
  if (!Array.isArray(list) || list.length === 0) return null;
  const i = rng.int(list.length);
  const entry = list[i];
  return typeof entry === 'object' && entry !== null ? [entry as Json, `${key}[${i}]`] : null;
}

function mutateGltfJson(json: Json, rng: Rng, applied: string[]): void {
  switch (rng.int(12)) {
    case 0: {
      const e = randomEntry(json, rng, ['accessors', 'bufferViews']);
      if (!e) return;
      const field = rng.pick(['byteOffset', 'byteStride', 'count', 'byteLength', 'bufferView', 'buffer']);
      e[0][field] = pickNumber(rng);
      applied.push(`${e[1]}.${field}=${e[0][field]}`);
      if (rng.chance(0.5)) {
        delete e[0].min;
        delete e[0].max;
      }
      return;
    }
    case 1: {
      const e = randomEntry(json, rng, ['accessors']);
      if (!e) return;
      e[0].componentType = rng.pick([5120, 5121, 5122, 5123, 5125, 5126, 5124, 0, '5126']);
      e[0].type = rng.pick(['SCALAR', 'VEC2', 'VEC3', 'VEC4', 'MAT2', 'MAT3', 'MAT4', 'VEC5', 3]);
      applied.push(`${e[1]} type=${e[0].type}/${e[0].componentType}`);
      return;
    }
    case 2: {
      // Huge arrays: copies of an entry (or of the whole list) up to 20 000.
      const key = rng.pick(['accessors', 'nodes', 'meshes', 'materials', 'bufferViews', 'buffers', 'cameras']);
      const list = Array.isArray(json[key]) ? (json[key] as unknown[]) : [];
      const wanted = rng.pick([100, 1000, 4097, 8193, 20_000]);
      const entry = list.length > 0 ? list[rng.int(list.length)] : { type: 'perspective', perspective: { yfov: 1, znear: 0.1 } };
      // Copies stop at twice the glTF JSON cap: a buffer whose data URI an earlier round made 400 kB,
      // copied 20 000 times, took the mutator (not the importer) past a 4 GB heap at seed 3532.
      const n = Math.max(1, Math.min(wanted, Math.floor((2 * MODEL_BYTE_CAPS.gltfJson) / JSON.stringify(entry).length)));
      json[key] = list.concat(Array.from({ length: n }, () => structuredClone(entry)));
      applied.push(`${key}×${n}`);
      return;
    }
    case 3: {
      const n = rng.pick([2, 63, 65, 1000, 300_000]);
      const scenes = Array.isArray(json.scenes) && json.scenes.length > 0 ? json.scenes : [{ nodes: [0] }];
      json.scenes = Array.from({ length: n }, (_, k) => scenes[k % scenes.length]);
      if (rng.chance(0.5)) json.scene = rng.chance(0.5) ? rng.int(n) : pickNumber(rng);
      applied.push(`scenes×${n}, scene=${json.scene}`);
      return;
    }
    case 4: {
      const e = randomEntry(json, rng, ['materials', 'nodes', 'meshes', 'scenes']);
      if (!e) return;
      e[0].name = longName(rng);
      applied.push(`${e[1]}.name (${(e[0].name as string).length} chars)`);
      return;
    }
    case 5: {
      const e = randomEntry(json, rng, ['nodes']);
      if (!e) return;
      const c = () => rng.pick([3.4e38, -3.4e38, 1e308, 1e20, 1e5, 100.5, 0, -1]);
      const field = rng.pick(['translation', 'scale', 'matrix', 'rotation']);
      e[0][field] = field === 'matrix' ? Array.from({ length: 16 }, (_, k) => (k % 5 === 0 ? c() : 0)) : field === 'rotation' ? [c(), 0, 0, 1] : [c(), c(), c()];
      applied.push(`${e[1]}.${field}`);
      return;
    }
    case 6: {
      const e = randomEntry(json, rng, ['accessors']);
      if (!e) return;
      e[0].sparse = {
        count: pickNumber(rng),
        indices: { bufferView: rng.int(4), byteOffset: pickNumber(rng), componentType: rng.pick([5121, 5123, 5125, 5126]) },
        values: { bufferView: rng.int(4), byteOffset: rng.chance(0.5) ? 0 : pickNumber(rng) },
      };
      applied.push(`${e[1]}.sparse`);
      return;
    }
    case 7: {
      // A primitive pointing elsewhere: indices, POSITION, material, mode.
      const meshes = Array.isArray(json.meshes) ? (json.meshes as Json[]) : [];
      const m = meshes[rng.int(Math.max(1, meshes.length))];
      const p = Array.isArray(m?.primitives) ? (m.primitives as Json[])[0] : undefined;
      if (!p) return;
      const field = rng.pick(['indices', 'material', 'mode', 'POSITION']);
      if (field === 'POSITION') (p.attributes as Json).POSITION = pickNumber(rng);
      else p[field] = field === 'mode' ? rng.int(8) : pickNumber(rng);
      applied.push(`primitive.${field}`);
      return;
    }
    case 8: {
      // Node graph: children that repeat, point back or out of range; instancing with many copies.
      const e = randomEntry(json, rng, ['nodes']);
      if (!e) return;
      if (rng.chance(0.5)) e[0].children = [rng.int(10), pickNumber(rng)];
      else e[0].extensions = { EXT_mesh_gpu_instancing: { attributes: { TRANSLATION: rng.int(4) } } };
      applied.push(`${e[1]} children/instancing`);
      return;
    }
    case 9: {
      const e = randomEntry(json, rng, ['buffers']);
      if (!e) return;
      e[0].byteLength = pickNumber(rng);
      if (rng.chance(0.3)) e[0].uri = rng.pick(['data:application/octet-stream;base64,' + 'QUFB'.repeat(rng.int(100_000)), 'data:,abc', 'missing.bin', '../../etc/passwd', '%zz']);
      applied.push(`${e[1]}.byteLength/uri`);
      return;
    }
    case 10: {
      const e = randomEntry(json, rng, ['materials']);
      if (!e) return;
      e[0].pbrMetallicRoughness = { baseColorFactor: rng.pick([[1e308, 0, 0, 1], [-1, 2, 0.5, 1], [0.5], 'red', [NaN]]) };
      applied.push(`${e[1]}.baseColorFactor`);
      return;
    }
    default: {
      const key = rng.pick(['accessors', 'bufferViews', 'nodes', 'meshes', 'scenes', 'buffers', 'asset', 'scene']);
      if (rng.chance(0.5)) delete json[key];
      else json[key] = rng.pick([null, 7, 'x', {}, [null], [[]]]);
      applied.push(`${key} replaced`);
    }
  }
}

/** A GLB's JSON and BIN chunks, or null when the container does not read. */
function splitGlb(bytes: Uint8Array): { json: string; bin: Uint8Array } | null {
  if (bytes.length < 20) return null;
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const jsonLength = view.getUint32(12, true);
  if (20 + jsonLength > bytes.length) return null;
  const json = decoder.decode(bytes.subarray(20, 20 + jsonLength));
  const at = 20 + jsonLength;
  const bin = at + 8 <= bytes.length ? bytes.subarray(at + 8, Math.min(bytes.length, at + 8 + view.getUint32(at, true))) : new Uint8Array(0);
  return { json, bin };
}

function buildGlb(jsonText: string, bin: Uint8Array): Uint8Array {
  const json = encoder.encode(jsonText);
  const jsonLength = Math.ceil(json.length / 4) * 4;
  const binLength = Math.ceil(bin.length / 4) * 4;
  const total = 20 + jsonLength + (bin.length > 0 ? 8 + binLength : 0);
  const out = new Uint8Array(total);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, 2, true);
  view.setUint32(8, total, true);
  view.setUint32(12, jsonLength, true);
  view.setUint32(16, 0x4e4f534a, true);
  out.set(json, 20);
  out.fill(0x20, 20 + json.length, 20 + jsonLength);
  if (bin.length > 0) {
    view.setUint32(20 + jsonLength, binLength, true);
    view.setUint32(24 + jsonLength, 0x004e4942, true);
    out.set(bin, 28 + jsonLength);
  }
  return out;
}

function mutateObjText(text: string, rng: Rng, applied: string[]): string {
  const lines = text.split('\n');
  const k = rng.int(lines.length);
  switch (rng.int(8)) {
    case 0:
      lines[k] = lines[k].replace(/-?\d+(\.\d+)?/, rng.pick(HUGE_COORDINATES));
      applied.push(`line ${k + 1}: huge number`);
      break;
    case 1:
      lines.splice(k, 0, `v ${rng.pick(HUGE_COORDINATES)} ${rng.pick(HUGE_COORDINATES)} 0`, 'f -1 -2 -3');
      applied.push('far vertex');
      break;
    case 2:
      lines[k] = lines[k].replace(/\d+/, String(rng.pick([0, -1, 99, 1e9, 2 ** 31])));
      applied.push(`line ${k + 1}: index`);
      break;
    case 3:
      lines.splice(k, 0, `usemtl ${longName(rng).replace(/\s/g, '_')}`);
      applied.push('long usemtl');
      break;
    case 4: {
      // Runs of lines: the scan must stop at its caps, not read to the end.
      const n = rng.pick([1000, 50_000, 250_000, 600_000]);
      const line = rng.pick(['v 0.1 0.2 0.3', 'f 1 2 3', 'vn 0 1 0', '# comment', 'f 1 2 3 4 5 6 7 8 9 10', 'g x']);
      lines.splice(k, 0, ...Array.from({ length: Math.min(n, 100_000) }, () => line));
      if (n > 100_000) lines.push(line.concat('\n').repeat(n - 100_000));
      applied.push(`${n}× "${line}"`);
      break;
    }
    case 5:
      lines[k] += rng.pick(['\\', '\u0000', '\r', ' \\\\', '\uFFFD']);
      applied.push(`line ${k + 1}: odd ending`);
      break;
    case 6:
      lines.splice(k, 1);
      applied.push(`line ${k + 1} removed`);
      break;
    default:
      lines.splice(k, 0, rng.pick(['mtllib ' + longName(rng), 'mtllib ../../x.mtl', 'Kd 1e308 -1 NaN', 'newmtl', 'f', 'v', 'o']));
      applied.push('odd statement');
  }
  return lines.join('\n');
}

function flipBytes(bytes: Uint8Array, rng: Rng, applied: string[]): Uint8Array {
  const out = bytes.slice();
  switch (rng.int(4)) {
    case 0: {
      const n = 1 + rng.int(8);
      for (let i = 0; i < n && out.length > 0; i++) out[rng.int(out.length)] ^= 1 << rng.int(8);
      applied.push(`${n} bit flips`);
      return out;
    }
    case 1:
      applied.push('truncated');
      return out.subarray(0, rng.int(out.length + 1));
    case 2: {
      // A 32-bit field overwritten (GLB lengths, chunk types, float coordinates).
      if (out.length < 4) return out;
      const at = rng.int(out.length - 3) & ~3;
      new DataView(out.buffer).setUint32(at, rng.pick([0, 0xffffffff, 0x7f7fffff, 0x7fc00000, out.length * 2, 0x46546c67]), true);
      applied.push(`u32 at ${at}`);
      return out;
    }
    default: {
      const at = rng.int(out.length + 1);
      const piece = out.subarray(rng.int(out.length + 1));
      applied.push(`splice at ${at}`);
      const merged = new Uint8Array(out.length + piece.length);
      merged.set(out.subarray(0, at));
      merged.set(piece, at);
      merged.set(out.subarray(at), at + piece.length);
      return merged;
    }
  }
}

/** One to three mutations of a copy of `seed`; returns the mutant and what was done. */
export function mutateBundle(seed: MeshBundle, rng: Rng): { bundle: MeshBundle; applied: string[] } {
  const applied: string[] = [];
  const files = seed.files.map((f) => ({ name: f.name, bytes: f.bytes }));
  const bundle: MeshBundle = { units: rng.chance(0.3) ? rng.pick(['auto', 'm', 'cm', 'mm', 'in'] as const) : seed.units, files };
  const rounds = 1 + rng.int(3);
  for (let r = 0; r < rounds; r++) {
    const i = rng.int(files.length);
    const f = files[i];
    if (rng.chance(0.2)) {
      f.bytes = flipBytes(f.bytes, rng, applied);
      continue;
    }
    if (/\.gltf$/i.test(f.name) || /\.glb$/i.test(f.name)) {
      const glb = /\.glb$/i.test(f.name) ? splitGlb(f.bytes) : null;
      let json: Json;
      try {
        json = JSON.parse(glb ? glb.json : decoder.decode(f.bytes)) as Json;
      } catch {
        f.bytes = flipBytes(f.bytes, rng, applied);
        continue;
      }
      if (typeof json !== 'object' || json === null) continue;
      mutateGltfJson(json, rng, applied);
      let text: string;
      try {
        text = JSON.stringify(json);
      } catch {
        // Mutations compounded past the longest string V8 makes: keep the file as it was.
        applied.push('(too large, reverted)');
        continue;
      }
      // Far past every cap already; larger only slows the campaign down.
      if (text.length > 64e6) {
        applied.push('(too large, reverted)');
        continue;
      }
      f.bytes = glb ? buildGlb(text, glb.bin) : encoder.encode(text);
    } else if (/\.(obj|mtl)$/i.test(f.name)) {
      f.bytes = encoder.encode(mutateObjText(decoder.decode(f.bytes), rng, applied));
    } else {
      f.bytes = flipBytes(f.bytes, rng, applied);
    }
  }
  if (rng.chance(0.03) && mainFile(bundle, /\.(obj|gltf|glb)$/i)) {
    const f = mainFile(bundle, /\.(obj|gltf|glb)$/i)!;
    f.name = `${'n'.repeat(rng.pick([150, 240]))}${f.name}`;
    applied.push('long file name');
  }
  return { bundle, applied };
}
