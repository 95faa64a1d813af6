import type { BakedMaps } from '../bake/bakedMaps';
import type { BakeSettings } from '../bake/bakeSettings';
import { resolveBakeSettings } from '../bake/bakeSettings';
import { createBaker, type BakeReport } from '../bake/createBaker';
import { createHeadlessGL } from './createHeadlessGL';
import { loadLightingSceneFile, type LoadedLightingScene } from './loadLightingSceneFile';

/** Load a scene file and bake it on a fresh headless-gl context (shared by `bake` and `probe`). */
export function bakeSceneFile(path: string, settings: Partial<BakeSettings>): { loaded: LoadedLightingScene; maps: BakedMaps; report: BakeReport } {
  resolveBakeSettings(settings);
  return bakeLoadedScene(loadLightingSceneFile(path), settings);
}

/** Bake an already loaded scene on a fresh headless-gl context. */
export function bakeLoadedScene(loaded: LoadedLightingScene, settings: Partial<BakeSettings>): { loaded: LoadedLightingScene; maps: BakedMaps; report: BakeReport } {
  const resolved = resolveBakeSettings(settings);
  const gl = createHeadlessGL();
  try {
    const { maps, report } = createBaker(gl).bake(loaded.bakeScene, resolved);
    return { loaded, maps, report };
  } finally {
    gl.destroy();
  }
}
