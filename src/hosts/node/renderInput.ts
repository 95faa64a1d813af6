import { existsSync } from 'node:fs';
import { basename, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { defaultCatalog } from '../../core/catalog/defaultCatalog';
import { LightingSceneError } from '../../core/model/lightingScene/parseLightingScene';
import type { Configuration } from '../../core/model/configuration/configuration';
import { deserializeConfiguration } from '../../core/model/files/sceneFile';
import { SCENE_FILE_FORMAT } from '../../core/model/files/sceneFileSchema';
import { toLightingScene } from '../../core/model/files/toLightingScene';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import { configurationMeshLoader } from '../../engines/view/configurationMeshLoader';
import { fixturesFromConfiguration, fixturesFromScene, type Fixtures } from '../../engines/view/fixtures';
import { resolveBakeSceneSync, SceneObjectError } from '../../engines/bake/resolveBakeScene';
import { InputError } from '../../core/inputError';
import { INPUT_LIMITS } from '../../core/untrustedJson';
import { loadLightingSceneFile, loadLightingSceneFileAsync, parseJsonText, resolveSceneFiles, type LoadedLightingScene, type SceneFileAccess } from './loadLightingSceneFile';
import { readRegularFile } from './readRegularFile';

/** What `luxbox render` draws: the baker's scene and the hardware to show. */
export interface RenderInput {
  scene: LightingScene;
  bakeScene: BakeScene;
  fixtures: Fixtures;
  kind: 'configuration' | 'lighting-scene';
  /** The configuration read (kind 'configuration'): its daylight settings are what --date/--time move (renderDaylightTime.ts). */
  configuration?: Configuration;
  /** The file's name, for messages. */
  source?: string;
}

/**
 * The app's public folder: the catalog's photometry paths ('ies/…') are
 * relative to it. $LUXBOX_PUBLIC_DIR wins; else public/ of the repository
 * this module is in (src/hosts/node/ from source, one level down when bundled into
 * gpu-pack/luxbox.mjs), else public/ of the working folder.
 */
export const PUBLIC_DIR = resolvePublicDir();

function resolvePublicDir(): string {
  if (process.env.LUXBOX_PUBLIC_DIR) return join(process.env.LUXBOX_PUBLIC_DIR, '/');
  const candidates = [fileURLToPath(new URL('../../../public/', import.meta.url)), fileURLToPath(new URL('../public/', import.meta.url)), join(process.cwd(), 'public/')];
  return candidates.find((dir) => existsSync(join(dir, 'ies'))) ?? candidates[0];
}

/**
 * Read a configurator scene file (format "luxbox-configuration", default
 * catalog, photometry from public/) or a lighting scene v1 (photometry
 * relative to the file), telling them apart by the format tag. `access`: where a lighting
 * scene's files may lie (the CLI passes cliReadableFolders). Lighting scenes' objects load from
 * OBJ only here; loadRenderInputAsync reads every mesh format.
 */
export function loadRenderInput(path: string, access: SceneFileAccess = {}): RenderInput {
  const file = readInputFile(path);
  return file.isConfiguration ? configurationInput(file.text, file.source) : lightingSceneInput(loadLightingSceneFile(path, access));
}

/** loadRenderInput for every mesh format (OBJ, glTF, GLB): what `luxbox render` and `export radiance` use. */
export async function loadRenderInputAsync(path: string, access: SceneFileAccess = {}): Promise<RenderInput> {
  const file = readInputFile(path);
  return file.isConfiguration ? configurationInput(file.text, file.source) : lightingSceneInput(await loadLightingSceneFileAsync(path, access));
}

function readInputFile(path: string): { source: string; text: string; isConfiguration: boolean } {
  const source = basename(path);
  let text: string;
  try {
    text = new TextDecoder('utf-8').decode(readRegularFile(path, { maxBytes: INPUT_LIMITS.maxTextLength }));
  } catch (error) {
    if (!(error instanceof InputError)) throw error;
    throw new LightingSceneError(error.message.startsWith('file is too large') ? `${source}: ${error.message}` : `${source}: cannot read ${path} (${error.message})`);
  }
  const data = parseJsonText(text, source);
  const isConfiguration = typeof data === 'object' && data !== null && (data as { format?: unknown }).format === SCENE_FILE_FORMAT;
  return { source, text, isConfiguration };
}

function lightingSceneInput(loaded: LoadedLightingScene): RenderInput {
  return { scene: loaded.scene, bakeScene: loaded.bakeScene, fixtures: fixturesFromScene(loaded.scene, loaded.bakeScene.luminaires), kind: 'lighting-scene' };
}

function configurationInput(text: string, source: string): RenderInput {
  return configurationRenderInput(deserializeConfiguration(text, defaultCatalog, source), source);
}

/** A configuration as `render` draws it: its lighting scene (as the app hands the baker), photometry from public/, its objects' meshes, its hardware. */
export function configurationRenderInput(config: Configuration, source: string): RenderInput {
  const scene = toLightingScene(config, defaultCatalog);
  // Photometry from public/ (the scene file's loader and messages); the objects' meshes from the configuration itself (`object:<id>`).
  const { bakeScene } = resolveSceneFiles({ ...scene, objects: [] }, PUBLIC_DIR, source);
  let objects: BakeScene['objects'];
  try {
    objects = resolveBakeSceneSync(
      { ...scene, luminaires: [] },
      () => {
        throw new Error('no photometry here');
      },
      configurationMeshLoader(config),
    ).objects;
  } catch (error) {
    throw error instanceof SceneObjectError ? new LightingSceneError(`${source}: ${error.message}`) : error;
  }
  return {
    scene,
    bakeScene: objects ? { ...bakeScene, objects } : bakeScene,
    fixtures: fixturesFromConfiguration(config, defaultCatalog, new Map(scene.luminaires.map((l, i) => [l.id ?? '', bakeScene.luminaires[i]]))),
    kind: 'configuration',
    configuration: config,
    source,
  };
}
