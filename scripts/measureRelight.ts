/**
 * Relight engine costs and the error of its between-solves approximation (docs/viewer.md,
 * "Relighting without rebaking"): per scene, the direct basis cost per group and the shared
 * indirect solve cost at the viewer's balanced quality, and for the first module of the scene
 * dimmed to 0.1 and to 0, the indirect light shown right after the change (last solve ×
 * Φ_now/Φ_solve) against the exact re-solve: RMS and worst texel of Y, relative to the mean and
 * the peak of the exact indirect Y, walls and the objects' covered atlas texels apart (every
 * texel weighted equally). Timings include shader compiles only in a first, untimed pass.
 * Run: xvfb-run -a npx tsx scripts/measureRelight.ts
 */
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { livingRoom } from '../src/core/catalog/furnishedPresets';
import { serializeConfiguration } from '../src/core/model/files/sceneFile';
import { luxOf } from '../src/engines/bake/bakedMaps';
import type { BakeScene } from '../src/engines/bake/bakeScene';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../src/engines/relight/createRelightEngine';
import type { LitMaps } from '../src/engines/relight/relightMaps';
import { SURFACE_NAMES } from '../src/core/model/lightingScene/lightingScene';
import { createHeadlessGL } from '../src/hosts/node/createHeadlessGL';
import { loadRenderInput } from '../src/hosts/node/renderInput';

/** Indirect Y per receiver (walls by name, then "objects": covered atlas texels only, the rest NaN). */
function indirectY(lit: LitMaps): { name: string; y: Float32Array }[] {
  const out = SURFACE_NAMES.map((n) => ({ name: n as string, y: luxOf(lit.maps[n].total.map((t, i) => t - lit.maps[n].direct[i])) }));
  const o = lit.maps.objects;
  if (o) {
    const y = luxOf(o.total.map((t, i) => t - o.direct[i]));
    for (let t = 0; t < y.length; t++) if (!(o.atlas.position[t * 4 + 3] > 0)) y[t] = Number.NaN;
    out.push({ name: 'objects', y });
  }
  return out;
}

/** RMS and worst |shown − exact| over a set of receivers, against the exact's mean and peak. */
function errorOf(shown: { name: string; y: Float32Array }[], exact: { name: string; y: Float32Array }[], pick: (name: string) => boolean): string {
  let sum = 0;
  let sq = 0;
  let peak = 0;
  let worst = 0;
  let where = '';
  let n = 0;
  exact.forEach(({ name, y }, r) => {
    if (!pick(name)) return;
    y.forEach((v, i) => {
      if (Number.isNaN(v)) return;
      const d = shown[r].y[i] - v;
      sum += v;
      sq += d * d;
      peak = Math.max(peak, v);
      if (Math.abs(d) > worst) {
        worst = Math.abs(d);
        where = `${name} (shown ${shown[r].y[i].toFixed(0)}, exact ${v.toFixed(0)} lx)`;
      }
      n++;
    });
  });
  if (n === 0) return 'none';
  const mean = sum / n;
  const rms = Math.sqrt(sq / n);
  return `RMS ${rms.toFixed(2)} lx = ${((100 * rms) / mean).toFixed(1)} % of the mean ${mean.toFixed(1)} lx, worst ${worst.toFixed(1)} lx = ${((100 * worst) / peak).toFixed(0)} % of the peak ${peak.toFixed(0)} lx at ${where}`;
}

function measure(label: string, scene: BakeScene): void {
  const gl = createHeadlessGL();
  const engine = createRelightEngine(gl, VIEWER_BAKE_SETTINGS);
  engine.setScene(scene);
  const groups = engine.progress.groups;
  // Warm-up pass over the same scene: shader compiles are per context and paid once, not per group.
  engine.finish();
  engine.dispose();
  const timed = createRelightEngine(gl, VIEWER_BAKE_SETTINGS);
  timed.setScene(scene);
  const t0 = performance.now();
  while (!timed.progress.lit) timed.step();
  const t1 = performance.now();
  timed.finish();
  const t2 = performance.now();
  console.log(`${label}: ${groups} groups, ${scene.objects?.length ?? 0} objects; direct bases ${((t1 - t0) / groups).toFixed(0)} ms per group; shared solve ${((t2 - t1) / 1000).toFixed(2)} s`);
  for (const dimming of [0.1, 0]) {
    const changed = { ...scene, luminaires: scene.luminaires.map((l, k) => (k === 0 ? { ...l, dimming } : l)) };
    timed.setScene(scene);
    timed.finish();
    timed.setScene(changed);
    const tr = performance.now();
    const lit = timed.maps();
    const relightMs = performance.now() - tr;
    const shown = indirectY(lit);
    const ts = performance.now();
    timed.finish();
    const solveMs = performance.now() - ts;
    const exact = indirectY(timed.maps());
    console.log(`  module 1 dimmed to ${dimming}: relight ${relightMs.toFixed(1)} ms, re-solve ${(solveMs / 1000).toFixed(2)} s`);
    console.log(`    walls: ${errorOf(shown, exact, (name) => name !== 'objects')}`);
    if (scene.objects?.length) console.log(`    objects (covered texels): ${errorOf(shown, exact, (name) => name === 'objects')}`);
  }
  timed.dispose();
  gl.destroy();
}

const cornerL = loadRenderInput(join(import.meta.dirname, '../tests/fixtures/configurations/corner-l.luxbox.json')).bakeScene;
const dir = mkdtempSync(join(tmpdir(), 'luxbox-relight-'));
const living = join(dir, 'living.luxbox.json');
writeFileSync(living, serializeConfiguration(livingRoom(defaultCatalog), defaultCatalog));
measure('corner-l (empty room)', cornerL);
measure('furnished living room', loadRenderInput(living).bakeScene);
