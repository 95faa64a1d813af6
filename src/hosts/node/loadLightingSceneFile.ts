import { basename, dirname, resolve } from 'node:path';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { LuminairePhotometryError, resolveBakeScene, resolveBakeSceneSync, SceneObjectError } from '../../engines/bake/resolveBakeScene';
import type { ImportedMesh } from '../../engines/meshImport/importedMesh';
import { LightingSceneError, parseLightingScene } from '../../core/model/lightingScene/parseLightingScene';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import { excerpt, INPUT_LIMITS, parseUntrustedJson } from '../../core/untrustedJson';
import { InputError } from '../../core/inputError';
import { PhotometryReadError } from '../../core/photometry/PhotometryReadError';
import type { Photometry } from '../../core/photometry/types';
import { createNodePhotometryLoader } from './createNodePhotometryLoader';
import { createNodeMeshLoader } from './createNodeMeshLoader';
import { readRegularFile } from './readRegularFile';

export interface LoadedLightingScene {
  scene: LightingScene;
  /** Parsed photometry per resolved path (each file read once, however many luminaires share it). */
  photometries: Map<string, Photometry>;
  /** Ready for the baker: photometry parsed, meshes loaded, defaults filled in. */
  bakeScene: BakeScene;
  /** Each object mesh as imported (units, triangle count, warnings), by the path the scene gives. */
  meshes: Map<string, ImportedMesh>;
}

/**
 * Parse JSON text under the shared input limits (size, syntax with line and
 * column, duplicate keys, nesting depth, array length), reporting problems as
 * one line `file: where: problem`.
 */
export function parseJsonText(text: string, source: string): unknown {
  return parseUntrustedJson(text, source, (message) => new LightingSceneError(message));
}

/** Where a scene's files may lie: `within` folders (absolute, real paths; absent: anywhere). The CLI passes cliReadableFolders. */
export interface SceneFileAccess {
  within?: readonly string[];
}

function readText(path: string, what: string): string {
  try {
    // A regular file, its size checked while reading: a mistaken argument (a video, /dev/zero) is refused, not read.
    return new TextDecoder('utf-8').decode(readRegularFile(path, { maxBytes: INPUT_LIMITS.maxTextLength }));
  } catch (error) {
    if (!(error instanceof InputError)) throw error;
    if (error.message.startsWith('file is too large')) throw new LightingSceneError(`${what}: ${error.message}`);
    throw new LightingSceneError(`${what}: cannot read ${path} (${error.message})`);
  }
}

/**
 * Read a lighting scene file and every photometric file it names, and its
 * objects' meshes when they are OBJ files (synchronously; glTF models need
 * loadLightingSceneFileAsync). Paths are relative to the scene file's folder
 * (absolute paths are kept).
 */
export function loadLightingSceneFile(path: string, access: SceneFileAccess = {}): LoadedLightingScene {
  const source = basename(path);
  const scene = parseLightingScene(parseJsonText(readText(path, source), source), source);
  return { scene, ...resolveSceneFiles(scene, dirname(resolve(path)), source, access) };
}

/** loadLightingSceneFile for every mesh format (OBJ, glTF, GLB): what `luxbox bake`, `probe` and `render` use. */
export async function loadLightingSceneFileAsync(path: string, access: SceneFileAccess = {}): Promise<LoadedLightingScene> {
  const source = basename(path);
  const scene = parseLightingScene(parseJsonText(readText(path, source), source), source);
  return { scene, ...(await resolveSceneFilesAsync(scene, dirname(resolve(path)), source, access)) };
}

/** A resolver failure as the one line the CLI prints: `<source>: luminaires[i].photometry: …` or `<source>: objects[i]…`. */
function sceneFileError(error: unknown, source: string): unknown {
  if (error instanceof SceneObjectError) return new LightingSceneError(`${source}: ${error.message}`);
  if (!(error instanceof LuminairePhotometryError)) return error;
  if (!(error.cause instanceof PhotometryReadError)) return error.cause;
  return new LightingSceneError(`${source}: luminaires[${error.luminaire}].photometry: cannot read ${excerpt(error.path)} (${error.cause.reason})`);
}

function photometriesOf(scene: LightingScene, folder: string, bakeScene: BakeScene): Map<string, Photometry> {
  return new Map(scene.luminaires.map((l, i) => [resolve(folder, l.photometry), bakeScene.luminaires[i].photometry]));
}

/** resolveSceneFiles for every mesh format (glTF is read asynchronously). */
export async function resolveSceneFilesAsync(scene: LightingScene, folder: string, source: string, access: SceneFileAccess = {}): Promise<Omit<LoadedLightingScene, 'scene'>> {
  const load = createNodePhotometryLoader(access);
  const meshLoader = createNodeMeshLoader(folder, access);
  let bakeScene: BakeScene;
  try {
    bakeScene = await resolveBakeScene(scene, (p) => load(resolve(folder, p)), meshLoader.load);
  } catch (error) {
    throw sceneFileError(error, source);
  }
  return { photometries: photometriesOf(scene, folder, bakeScene), bakeScene, meshes: meshLoader.imported };
}

/**
 * The baker's scene for a lighting scene whose photometry paths are relative
 * to `folder`, with the parsed files by absolute path. A file that cannot be
 * read is `<source>: luminaires[i].photometry: cannot read "<path>" (no such
 * file)`, the path as the scene wrote it; one that does not parse is the
 * parser's own error (it names the file).
 */
export function resolveSceneFiles(scene: LightingScene, folder: string, source: string, access: SceneFileAccess = {}): Omit<LoadedLightingScene, 'scene'> {
  const load = createNodePhotometryLoader(access);
  const meshLoader = createNodeMeshLoader(folder, access);
  let bakeScene: BakeScene;
  try {
    bakeScene = resolveBakeSceneSync(scene, (p) => load(resolve(folder, p)), meshLoader.loadSync);
  } catch (error) {
    throw sceneFileError(error, source);
  }
  return { photometries: photometriesOf(scene, folder, bakeScene), bakeScene, meshes: meshLoader.imported };
}
