import { InputError } from '../../core/inputError';
import { excerpt, jsonShapeProblem, oneLine } from '../../core/untrustedJson';
import { decodeText } from './decodeText';
import type { MeshFile, MeshImportOptions } from './importedMesh';
import { shortName } from './readMtlMaterials';
import { checkByteCap, MODEL_BYTE_CAPS } from './byteCaps';
import { checkGltfAccessors, checkPrimitiveIndices } from './checkGltfAccessors';
import { checkGltfCounts } from './gltfCountCaps';
import { checkTriangleBudget } from './triangleBudget';
import type { Json, GltfJson } from './gltfJson';
import { list } from './gltfJson';
import { GLB_MAGIC, readU32 } from './readGlb';
import { DROPPED_EXTENSIONS } from './stripTextures';
import { stripTextures } from './stripTextures';
import { packBuffers } from './packBuffers';
import { fillPositionBounds } from './fillPositionBounds';
import { sceneTriangles } from './sceneTriangles';
import { keepDefaultScene } from './keepDefaultScene';
import { readGlb } from './readGlb';
import { buildGlb } from './buildGlb';

export type { GltfJson } from './gltfJson';

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
