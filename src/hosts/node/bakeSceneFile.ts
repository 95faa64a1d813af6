import type { BakedMaps } from '../../engines/bake/bakedMaps';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { BakeSettings } from '../../engines/bake/bakeSettings';
import { resolveBakeSettings } from '../../engines/bake/bakeSettings';
import { createBaker, type BakeReport } from '../../engines/bake/createBaker';
import { cachedProgramCount } from '../../engines/bake/glResources';
import { createHeadlessGL } from './createHeadlessGL';
import { loadLightingSceneFile, type LoadedLightingScene } from './loadLightingSceneFile';

export interface SceneBaker {
  /** Bake a loaded scene (settings resolved by the baker, or passed on as resolveBakeSettings gave them); programs compiled by earlier bakes of this SceneBaker are reused. */
  bake(loaded: LoadedLightingScene, settings: Partial<BakeSettings>): { loaded: LoadedLightingScene; maps: BakedMaps; report: BakeReport };
  /** Bake a scene as the baker takes it on the same context (the daylight report's further bakes, daylightReport.ts). */
  bakeScene(scene: BakeScene, settings: Partial<BakeSettings>): { maps: BakedMaps; report: BakeReport };
  /** Programs compiled so far on this context (a batch compiles each distinct shader once). */
  programCount(): number;
  destroy(): void;
}

/**
 * One headless-gl context and baker for many bakes: the program cache lives
 * as long as the context, so a batch (`luxbox bake a.json b.json …`) pays each
 * shader compile once.
 */
export function createSceneBaker(): SceneBaker {
  const gl = createHeadlessGL();
  const baker = createBaker(gl);
  return {
    bake(loaded, settings) {
      const { maps, report } = baker.bake(loaded.bakeScene, settings);
      return { loaded, maps, report };
    },
    bakeScene: (scene, settings) => baker.bake(scene, settings),
    programCount: () => cachedProgramCount(gl),
    destroy: () => gl.destroy(),
  };
}

/** Load a scene file and bake it on a fresh headless-gl context (shared by `bake` and `probe`). */
export function bakeSceneFile(path: string, settings: Partial<BakeSettings>): { loaded: LoadedLightingScene; maps: BakedMaps; report: BakeReport } {
  // Checked before the scene file is read; the resolved settings go on as they are.
  const resolved = resolveBakeSettings(settings);
  return bakeLoadedScene(loadLightingSceneFile(path), resolved);
}

/** Bake an already loaded scene on a fresh headless-gl context. */
export function bakeLoadedScene(loaded: LoadedLightingScene, settings: Partial<BakeSettings>): { loaded: LoadedLightingScene; maps: BakedMaps; report: BakeReport } {
  const sceneBaker = createSceneBaker();
  try {
    return sceneBaker.bake(loaded, settings);
  } finally {
    sceneBaker.destroy();
  }
}
