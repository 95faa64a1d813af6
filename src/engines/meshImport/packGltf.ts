import { InputError } from '../../core/inputError';
import { excerpt, jsonShapeProblem, oneLine } from '../../core/untrustedJson';
import { decodeText } from './decodeText';
import { findFile } from './findFile';
import type { MeshFile, MeshImportOptions } from './importedMesh';
import { shortName } from './readMtlMaterials';
import { checkByteCap, MODEL_BYTE_CAPS } from './byteCaps';
import { checkGltfAccessors, checkPrimitiveIndices } from './checkGltfAccessors';
import { checkGltfCounts } from './gltfCountCaps';
import { checkTriangleBudget, formatCount, MAX_IMPORT_TRIANGLES } from './triangleBudget';

/** glTF 2.0 §4.4 "Binary glTF Layout": header magic "glTF", chunk types "JSON" and "BIN\0". */
const GLB_MAGIC = 0x46546c67;
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;

/** Extensions that only change shading or textures: dropped with the textures (luxbox reads a base colour factor). */
const DROPPED_EXTENSIONS = /^(KHR_materials_|KHR_texture_|EXT_texture_|MSFT_texture_)/;
/** Extensions three's GLTFLoader reads without extra decoders. */
const READABLE_EXTENSIONS = new Set(['KHR_mesh_quantization', 'EXT_mesh_gpu_instancing', 'KHR_lights_punctual']);
/**
 * glTF JSON nests about 6 levels deep; its longest arrays are the capped top-level ones
 * (gltfCountCaps.ts, at most 8 192) and a node's children: 65 536 bounds what else (extras) may hold.
 */
const GLTF_JSON_LIMITS = { maxDepth: 64, maxArrayLength: 65_536 } as const;

export interface PackedGltf {
  name: string;
  /** A self-contained GLB (every buffer in its BIN chunk, no textures) for GLTFLoader.parse. */
  glb: ArrayBuffer;
  /** Its JSON (materials with their base colour factors, read by index). */
  json: GltfJson;
  warnings: string[];
}

type Json = Record<string, unknown>;
export interface GltfJson extends Json {
  materials?: Json[];
}

/**
 * A glTF (.gltf with embedded data-URI or external buffers, or .glb) made self-contained for
 * three's GLTFLoader: the container checked (magic, version, lengths, chunks), every buffer
 * resolved (GLB chunk, base64 data URI, or an external file among `files` or read through
 * `options.readFile`) and concatenated into one BIN chunk, images and textures removed (luxbox
 * needs geometry and base colour factors; Node has no image decoder), the node hierarchy checked
 * for cycles, and the triangle count checked against the budget before any geometry is built.
 * Every input is bounded before it is decoded (byteCaps.ts), array counts are capped
 * (gltfCountCaps.ts), every accessor is checked against its buffer view (checkGltfAccessors.ts),
 * and only the default scene is kept (GLTFLoader builds every scene of a file).
 * GLTFLoader itself then fetches nothing: in Node its FileLoader cannot even read a data URI (it
 * needs the browser's ProgressEvent; three 0.187), and without images it needs no image decoder.
 */
export async function packGltf(files: readonly MeshFile[], options: MeshImportOptions): Promise<PackedGltf> {
  const main = files.find((f) => /\.(gltf|glb)$/i.test(f.name));
  if (!main) throw new InputError(`no .gltf or .glb file among ${files.map((f) => f.name).join(', ') || 'the files given'}`);
  const name = main.name;
  const fail: (problem: string) => never = (problem) => {
    // One line of bounded length, whatever the file put into the values quoted.
    throw new InputError(oneLine(`${name}: ${problem}`));
  };
  const isGlb = main.bytes.length >= 4 && readU32(main.bytes, 0) === GLB_MAGIC;
  if (/\.glb$/i.test(name) && !isGlb) fail(`not a GLB file (the first 4 bytes are not "glTF")`);
  if (isGlb) checkByteCap(name, main.bytes.length, MODEL_BYTE_CAPS.glb, 'a GLB file');
  else checkByteCap(name, main.bytes.length, MODEL_BYTE_CAPS.gltfJson, 'glTF JSON');
  const { text, bin } = isGlb ? readGlb(main.bytes, fail) : { text: decodeText(main.bytes), bin: undefined };
  let parsed: unknown;
  try {
    parsed = JSON.parse(text);
  } catch (error) {
    fail(`invalid JSON (${error instanceof Error ? oneLine(error.message, 80) : 'syntax error'})`);
  }
  if (typeof parsed !== 'object' || parsed === null || Array.isArray(parsed)) fail('the glTF JSON is not an object');
  // The top-level counts first (no recursion, and a 300 000-scene file stops here at once).
  checkGltfCounts(parsed as Json, fail);
  // Nothing below (nor GLTFLoader) may recurse into a hostile nesting depth.
  const shape = jsonShapeProblem(parsed, GLTF_JSON_LIMITS);
  if (shape) fail(shape);
  const json = parsed as GltfJson;
  const asset = json.asset as Json | undefined;
  const version = typeof asset === 'object' && asset !== null ? asset.version : undefined;
  if (typeof version !== 'string' || !version.startsWith('2.')) fail(`asset.version ${excerpt(version ?? null)} (luxbox reads glTF 2.0)`);

  const required = list(json, 'extensionsRequired', fail).map(String);
  for (const ext of required) {
    if (READABLE_EXTENSIONS.has(ext) || DROPPED_EXTENSIONS.test(ext)) continue;
    const hint = /draco|meshopt/i.test(ext) ? 'compressed geometry; export without compression' : 'not supported';
    fail(`needs the extension ${shortName(ext)} (${hint})`);
  }
  const warnings: string[] = [];
  stripTextures(json, name, warnings, fail);
  const binary = await packBuffers(json, bin, files, options, name, fail);
  checkGltfAccessors(json, binary, fail);
  checkPrimitiveIndices(json, binary, fail);
  checkTriangleBudget(name, sceneTriangles(json, fail));
  keepDefaultScene(json);
  fillPositionBounds(json, binary);
  return { name, glb: buildGlb(JSON.stringify(json, forLoader), binary), json, warnings };
}

/**
 * The JSON as GLTFLoader gets it: a baseColorFactor that is not four finite numbers is left out
 * (the loader would print "parameter 'opacity' has value of undefined" on the CLI's stderr);
 * importGltfMesh still reads the original from `json`, warns and uses grey.
 */
function forLoader(key: string, value: unknown): unknown {
  if (key !== 'baseColorFactor') return value;
  return Array.isArray(value) && value.length === 4 && value.every((x) => typeof x === 'number' && Number.isFinite(x)) ? value : undefined;
}

function readU32(bytes: Uint8Array, offset: number): number {
  return new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength).getUint32(offset, true);
}

/** The JSON text and BIN chunk of a GLB, every length checked against the file. */
function readGlb(bytes: Uint8Array, fail: (p: string) => never): { text: string; bin: Uint8Array | undefined } {
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

/** A top-level or nested array field; absent = []; anything else is an error naming the field. */
function list(parent: Json, key: string, fail: (p: string) => never, where = key): unknown[] {
  const value = parent[key];
  if (value === undefined) return [];
  if (!Array.isArray(value)) fail(`${where} must be an array`);
  return value as unknown[];
}

function objectAt(array: unknown[], i: number, where: string, fail: (p: string) => never): Json {
  const value = array[i];
  if (typeof value !== 'object' || value === null || Array.isArray(value)) fail(`${where}[${i}] must be an object`);
  return value as Json;
}

/** Remove images, textures and texture references; a base-colour texture leaves a warning (its factor is used). */
function stripTextures(json: GltfJson, name: string, warnings: string[], fail: (p: string) => never): void {
  const materials = list(json, 'materials', fail);
  let textured = 0;
  materials.forEach((_, i) => {
    const m = objectAt(materials, i, 'materials', fail);
    const pbr = m.pbrMetallicRoughness;
    if (typeof pbr === 'object' && pbr !== null && !Array.isArray(pbr)) {
      const p = pbr as Json;
      if (p.baseColorTexture !== undefined) {
        textured++;
        if (textured <= 3) warnings.push(`${name}: material '${shortName(String(m.name ?? `materials[${i}]`))}' has a base-colour texture; luxbox uses its base colour factor`);
      }
      delete p.baseColorTexture;
      delete p.metallicRoughnessTexture;
    }
    delete m.normalTexture;
    delete m.occlusionTexture;
    delete m.emissiveTexture;
    delete m.extensions;
  });
  if (textured > 3) warnings.push(`${name}: ${textured - 3} more materials have base-colour textures (factors used)`);
  delete json.images;
  delete json.textures;
  delete json.samplers;
  delete json.animations;
  for (const key of ['extensionsUsed', 'extensionsRequired']) {
    const exts = list(json, key, fail);
    json[key] = exts.filter((e) => typeof e === 'string' && !DROPPED_EXTENSIONS.test(e));
  }
}

/** Every buffer's bytes in one BIN chunk (8-byte aligned), buffer views pointed at it. */
async function packBuffers(json: GltfJson, glbBin: Uint8Array | undefined, files: readonly MeshFile[], options: MeshImportOptions, name: string, fail: (p: string) => never): Promise<Uint8Array> {
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

/**
 * POSITION accessors must carry min and max (glTF 2.0 §3.7.2.1); GLTFLoader warns on the console
 * when they are missing, which would break the CLI's promise of an empty stderr. Fill them in for
 * plain float positions (what exporters write when they omit them); anything else stays as it is.
 */
function fillPositionBounds(json: GltfJson, binary: Uint8Array): void {
  const accessors = (json.accessors ?? []) as Json[];
  const views = (json.bufferViews ?? []) as Json[];
  const data = new DataView(binary.buffer, binary.byteOffset, binary.byteLength);
  const positionAccessors = new Set<number>();
  for (const mesh of (json.meshes ?? []) as Json[]) {
    for (const p of (Array.isArray(mesh?.primitives) ? mesh.primitives : []) as Json[]) {
      const k = (p?.attributes as Json | undefined)?.POSITION;
      if (typeof k === 'number') positionAccessors.add(k);
    }
  }
  for (const k of positionAccessors) {
    const a = accessors[k];
    if (!a || (Array.isArray(a.min) && Array.isArray(a.max)) || a.componentType !== 5126 || a.type !== 'VEC3' || a.sparse !== undefined) continue;
    const view = typeof a.bufferView === 'number' ? views[a.bufferView] : undefined;
    if (!view) continue;
    const start = (view.byteOffset as number) + (typeof a.byteOffset === 'number' ? a.byteOffset : 0);
    const stride = typeof view.byteStride === 'number' ? view.byteStride : 12;
    const count = a.count as number;
    const end = (view.byteOffset as number) + (view.byteLength as number);
    if (count === 0 || start + (count - 1) * stride + 12 > end) continue;
    const min = [Infinity, Infinity, Infinity];
    const max = [-Infinity, -Infinity, -Infinity];
    for (let i = 0; i < count; i++) {
      for (let c = 0; c < 3; c++) {
        const v = data.getFloat32(start + i * stride + 4 * c, true);
        min[c] = Math.min(min[c], v);
        max[c] = Math.max(max[c], v);
      }
    }
    if (min.every(Number.isFinite) && max.every(Number.isFinite)) {
      a.min = min;
      a.max = max;
    }
  }
}

/**
 * Triangles of the default scene, from the JSON (glTF 2.0 §3.7.2.1: mode 4 triangles, 5 strip,
 * 6 fan; points and lines have none), each node's mesh counted once per use; the node graph
 * must be a forest (§3.5.3), which also rules out cycles before GLTFLoader walks it.
 */
function sceneTriangles(json: GltfJson, fail: (p: string) => never): number {
  const scenes = list(json, 'scenes', fail);
  if (scenes.length === 0) fail('no scene');
  const sceneIndex = json.scene ?? 0;
  if (typeof sceneIndex !== 'number' || !Number.isInteger(sceneIndex) || sceneIndex < 0 || sceneIndex >= scenes.length) fail(`scene ${excerpt(sceneIndex)} is not one of the file's scenes`);
  const nodes = list(json, 'nodes', fail);
  const meshes = list(json, 'meshes', fail);
  const accessors = list(json, 'accessors', fail);
  const countOf = (k: unknown): number => {
    if (typeof k !== 'number' || !Number.isInteger(k) || k < 0 || k >= accessors.length) fail(`a primitive refers to accessor ${excerpt(k ?? null)}, which does not exist`);
    return (accessors[k as number] as Json).count as number;
  };
  const meshTriangles = (m: unknown): number => {
    if (typeof m !== 'number' || !Number.isInteger(m) || m < 0 || m >= meshes.length) fail(`a node refers to mesh ${excerpt(m)}, which does not exist`);
    const mesh = objectAt(meshes, m as number, 'meshes', fail);
    let n = 0;
    for (const [pi, primitive] of list(mesh, 'primitives', fail, `meshes[${m}].primitives`).entries()) {
      if (typeof primitive !== 'object' || primitive === null) fail(`meshes[${m}].primitives[${pi}] must be an object`);
      const p = primitive as Json;
      const attributes = p.attributes as Json | undefined;
      if (typeof attributes !== 'object' || attributes === null || attributes.POSITION === undefined) fail(`meshes[${m}].primitives[${pi}] has no POSITION attribute`);
      const vertices = p.indices !== undefined ? countOf(p.indices) : countOf(attributes!.POSITION);
      const mode = p.mode ?? 4;
      if (mode === 4) n += Math.floor(vertices / 3);
      else if (mode === 5 || mode === 6) n += Math.max(0, vertices - 2);
    }
    return n;
  };
  const seen = new Set<number>();
  let triangles = 0;
  const stack = list(objectAt(scenes, sceneIndex as number, 'scenes', fail), 'nodes', fail, `scenes[${sceneIndex}].nodes`).slice();
  while (stack.length > 0) {
    const k = stack.pop();
    if (typeof k !== 'number' || !Number.isInteger(k) || k < 0 || k >= nodes.length) fail(`the scene refers to node ${excerpt(k ?? null)}, which does not exist`);
    if (seen.has(k as number)) fail(`nodes[${k}] appears twice in the node hierarchy (it must be a tree)`);
    seen.add(k as number);
    const node = objectAt(nodes, k as number, 'nodes', fail);
    const instancing = (node.extensions as Json | undefined)?.EXT_mesh_gpu_instancing as Json | undefined;
    const instanceAccessor = (instancing?.attributes as Json | undefined)?.TRANSLATION ?? (instancing?.attributes as Json | undefined)?.ROTATION ?? (instancing?.attributes as Json | undefined)?.SCALE;
    const copies = instanceAccessor !== undefined ? countOf(instanceAccessor) : 1;
    // Instances of a mesh without triangles add none, but GLTFLoader still builds a matrix for each.
    if (copies > MAX_IMPORT_TRIANGLES) fail(`nodes[${k}] has ${formatCount(copies)} instances; at most ${formatCount(MAX_IMPORT_TRIANGLES)}`);
    if (node.mesh !== undefined) triangles += meshTriangles(node.mesh) * copies;
    for (const child of list(node, 'children', fail, `nodes[${k}].children`)) stack.push(child);
  }
  return triangles;
}

/**
 * Only the default scene (`scene`, else the first) as the file's one scene: GLTFLoader builds every
 * scene (issue 32: a GLB declaring 285 714 scenes took 30 s), luxbox imports one. Cameras are
 * dropped too (a camera carries no surface; GLTFLoader would build each).
 */
function keepDefaultScene(json: GltfJson): void {
  const scenes = json.scenes as unknown[];
  json.scenes = [scenes[(json.scene as number | undefined) ?? 0]];
  json.scene = 0;
  delete json.cameras;
  for (const node of (Array.isArray(json.nodes) ? json.nodes : []) as unknown[]) if (typeof node === 'object' && node !== null) delete (node as Json).camera;
}

/** A GLB container (§4.4) holding `jsonText` and `binary`. */
function buildGlb(jsonText: string, binary: Uint8Array): ArrayBuffer {
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
