/**
 * Blotchiness of the indirect light (docs/baker.md, "Noise of the indirect light"): the furnished
 * dining room baked at a quality level, then per wall the RMS of the indirect illuminance about its
 * least-squares bicubic fit (the smooth part; irradiance from distant surfaces varies slowly),
 * relative to the wall's mean, area-weighted over the four walls; and the same maps against a
 * bake of `factor` × the samples (default 8, as tests/engines/bake/indirectNoise.test.ts; same seed and
 * blur). Bake times of the level (seeds 1…repeats, after one untimed bake that compiles) in the same process.
 * Run: xvfb-run -a npx tsx scripts/measureIndirectNoise.ts [fast|balanced|best] [repeats] [factor]
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { diningRoom } from '../src/core/catalog/furnishedPresets';
import { serializeConfiguration } from '../src/core/model/files/sceneFile';
import { resolveBakeSettings } from '../src/engines/bake/bakeSettings';
import { createBaker } from '../src/engines/bake/createBaker';
import { isQualityLevel, QUALITY_LEVELS } from '../src/engines/relight/qualityLevels';
import { createHeadlessGL } from '../src/hosts/node/createHeadlessGL';
import { loadRenderInput } from '../src/hosts/node/renderInput';
import { wallBlotchiness, wallDeviation } from '../tests/engines/bake/indirectNoise';

const level = process.argv[2] ?? 'fast';
if (!isQualityLevel(level)) throw new Error(`unknown quality level ${level}`);
const repeats = Number(process.argv[3] ?? 3);
const factor = Number(process.argv[4] ?? 8);
const dir = mkdtempSync(join(tmpdir(), 'luxbox-noise-'));
const file = join(dir, 'dining.luxbox.json');
writeFileSync(file, serializeConfiguration(diningRoom(defaultCatalog), defaultCatalog));
const scene = loadRenderInput(file).bakeScene;
const gl = createHeadlessGL();
const baker = createBaker(gl);
const settings = resolveBakeSettings({ ...QUALITY_LEVELS[level], seed: 1 });
baker.bake(scene, settings); // untimed: compiles and prepares the objects
const times: number[] = [];
let maps = null as ReturnType<typeof baker.bake>['maps'] | null;
for (let r = 0; r < repeats; r++) {
  const t0 = performance.now();
  const baked = baker.bake(scene, { ...settings, seed: 1 + r }).maps;
  times.push(performance.now() - t0);
  if (r === 0) maps = baked;
}
if (!maps) throw new Error('repeats must be at least 1');
const converged = baker.bake(scene, resolveBakeSettings({ ...settings, samples: settings.samples * factor })).maps;
const median = [...times].sort((a, b) => a - b)[Math.floor(times.length / 2)];
console.log(
  `${level}: bake ${times.map((t) => t.toFixed(0)).join(', ')} ms (median ${median.toFixed(0)}); walls' indirect about a bicubic fit ${(100 * wallBlotchiness(maps)).toFixed(2)} %; ${factor}× the samples: ${(100 * wallBlotchiness(converged)).toFixed(2)} %; against ${factor}× the samples ${(100 * wallDeviation(maps, converged)).toFixed(2)} %`,
);
baker.dispose();
gl.destroy();
