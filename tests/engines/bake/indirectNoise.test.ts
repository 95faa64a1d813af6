import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { diningRoom } from '../../../src/core/catalog/furnishedPresets';
import { serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { QUALITY_LEVELS } from '../../../src/engines/relight/qualityLevels';
import { loadRenderInput } from '../../../src/hosts/node/renderInput';
import { cubicFit, wallBlotchiness, wallDeviation, WALLS } from './indirectNoise';
import { withHeadlessGL } from './withHeadlessGL';

/**
 * Blotches on the walls (issue 26, docs/baker.md "Noise of the indirect light"): the furnished dining
 * room at the 3D view's `fast` level (0.1 m texels, 32 samples, 2 bounces, blur radius 3), whose
 * walls are lit almost only by the first bounce of the three spots' pools on the table top (21 klx
 * on the table, 2 lx direct on the walls). The walls' indirect maps are compared with a bake of 8×
 * the samples (same seed, settings and blur): the RMS of the difference, relative to each wall's
 * mean, is the noise a shopper sees as low-frequency blotches once the blur has spread it.
 * Measured: 15.4 % before the pools on furniture became bright patches, 1.97 % after.
 */
const gl = withHeadlessGL();

function diningScene() {
  const file = join(mkdtempSync(join(tmpdir(), 'luxbox-noise-')), 'dining.luxbox.json');
  writeFileSync(file, serializeConfiguration(diningRoom(defaultCatalog), defaultCatalog));
  return loadRenderInput(file).bakeScene;
}

describe('noise of the indirect light', () => {
  it('the cubic fit reproduces a cubic field exactly and its residual is 0', () => {
    const w = 9;
    const h = 7;
    const field = new Float32Array(w * h);
    for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) field[j * w + i] = 40 + 3 * i - 0.5 * j * j + 0.02 * i * i * j;
    const fit = cubicFit(field, w, h);
    for (let t = 0; t < field.length; t++) expect(fit[t]).toBeCloseTo(field[t], 3);
  });

  it('fast level, furnished dining room: the walls’ indirect light within 4 % RMS of 8× the samples (pure Monte Carlo: over 10 %)', { timeout: 300_000 }, () => {
    const scene = diningScene();
    const baker = createBaker(gl);
    const fast = resolveBakeSettings({ ...QUALITY_LEVELS.fast, seed: 1 });
    const maps = baker.bake(scene, fast).maps;
    const converged = baker.bake(scene, resolveBakeSettings({ ...fast, samples: 8 * fast.samples })).maps;
    const pureMonteCarlo = baker.bake(scene, resolveBakeSettings({ ...fast, brightPatches: 0 })).maps;
    const deviation = wallDeviation(maps, converged);
    const noisy = wallDeviation(pureMonteCarlo, converged);
    console.log(
      `walls' indirect at fast against 8× the samples: ${(100 * deviation).toFixed(2)} % RMS (pure Monte Carlo ${(100 * noisy).toFixed(2)} %); about a cubic fit ${(100 * wallBlotchiness(maps)).toFixed(2)} % (8× the samples ${(100 * wallBlotchiness(converged)).toFixed(2)} %)`,
    );
    expect(deviation).toBeLessThan(0.04);
    // The measure sees blotches: the gather without bright patches is the picture the issue showed.
    expect(noisy).toBeGreaterThan(0.1);
    for (const wall of WALLS) for (const x of maps[wall].indirect) expect(Number.isFinite(x) && x >= 0).toBe(true);
    baker.dispose();
  });
});
