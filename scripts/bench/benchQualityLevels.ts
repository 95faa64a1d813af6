/**
 * Time to first lit frame and to done per quality level (issue #15, docs/benchmarks.md "3D
 * lifecycle"): the relight engine on headless-gl, a fresh context per bake (a first toggle:
 * programs compile inside the timing), for the L-corner preset in the default room and the
 * furnished living room (src/core/catalog/furnishedPresets.ts: 6 × 5 m, corner-l rail, seven
 * objects). Also the device calibration and the level `chooseQuality` picks from it.
 * Run alone: xvfb-run -a npx tsx scripts/bench/benchQualityLevels.ts
 */
import { readFileSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { defaultCatalog } from '../../src/core/catalog/defaultCatalog';
import { livingRoom } from '../../src/core/catalog/furnishedPresets';
import { createConfiguration, type Configuration } from '../../src/core/model/configuration/configuration';
import { createConfiguratorStore } from '../../src/core/store/createConfiguratorStore';
import { toLightingScene } from '../../src/core/model/files/toLightingScene';
import { parsePhotometry } from '../../src/core/photometry/parsePhotometry';
import type { BakeScene } from '../../src/engines/bake/bakeScene';
import { resolveBakeSceneSync } from '../../src/engines/bake/resolveBakeScene';
import { calibrateBakeSpeed, chooseQuality, predictQuality, type BakeCalibration, type QualityPrediction } from '../../src/engines/relight/calibrateBakeSpeed';
import { QUALITY_LEVEL_NAMES, QUALITY_LEVELS, type QualityLevel } from '../../src/engines/relight/qualityLevels';
import { configurationMeshLoader } from '../../src/engines/view/configurationMeshLoader';
import { createHeadlessGL } from '../../src/hosts/node/createHeadlessGL';
import { PUBLIC_DIR } from '../../src/hosts/node/renderInput';
import { timeEngineBake, type EngineBakeTiming } from './timeEngineBake';

export interface QualityLevelRow extends EngineBakeTiming {
  scene: string;
  level: QualityLevel;
}

export interface QualityBenchResult {
  rows: QualityLevelRow[];
  calibration: BakeCalibration;
  /** The calibration bake's own wall time (cold + warm), ms. */
  calibrationMs: number;
  predictions: QualityPrediction[];
  chosen: QualityLevel;
}

/** A configuration's bake scene as the 3D view resolves it (photometry from public/, meshes from the configuration). */
export function configurationBakeScene(config: Configuration): BakeScene {
  return resolveBakeSceneSync(toLightingScene(config, defaultCatalog), (path) => parsePhotometry(readFileSync(PUBLIC_DIR + path), path), configurationMeshLoader(config));
}

export function presetConfiguration(presetId: string): Configuration {
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
  if (!store.getState().dispatch('placePreset', { presetId }).ok) throw new Error(`cannot place preset ${presetId}`);
  return store.getState().config;
}

export const QUALITY_BENCH_SCENES: readonly { name: string; build: () => Configuration }[] = [
  { name: 'corner-l (5 × 4 × 2.8 m, 6 modules)', build: () => presetConfiguration('corner-l') },
  { name: 'living room, furnished (6 × 5 × 2.7 m, 6 modules, 7 objects)', build: () => livingRoom(defaultCatalog) },
];

export function benchQualityLevels(log: (line: string) => void = console.log): QualityBenchResult {
  const gl = createHeadlessGL();
  let calibration: BakeCalibration;
  const c0 = performance.now();
  try {
    calibration = calibrateBakeSpeed(gl);
  } finally {
    gl.destroy();
  }
  const calibrationMs = performance.now() - c0;
  const predictions = predictQuality(calibration);
  const chosen = chooseQuality(calibration);
  log(`calibration ${calibrationMs.toFixed(0)} ms: ${JSON.stringify(calibration)} → ${chosen}`);
  const rows: QualityLevelRow[] = [];
  for (const s of QUALITY_BENCH_SCENES) {
    const scene = configurationBakeScene(s.build());
    for (const level of QUALITY_LEVEL_NAMES) {
      const ctx = createHeadlessGL();
      try {
        const t = timeEngineBake(ctx, scene, QUALITY_LEVELS[level]);
        rows.push({ scene: s.name, level, ...t });
        log(`${s.name} ${level}: lit ${t.litMs.toFixed(0)} ms, done ${t.doneMs.toFixed(0)} ms`);
      } finally {
        ctx.destroy();
      }
    }
  }
  return { rows, calibration, calibrationMs, predictions, chosen };
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) benchQualityLevels();
