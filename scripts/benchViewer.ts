/**
 * Viewer benchmarks (docs/benchmarks.md, "Viewer"): relight vs full rebake
 * (headless-gl, same run), gzip sizes of the planner entry bundle and the 3D
 * chunk (from dist/, run `npx vite build` first), and toggle → first lit frame
 * in Chromium (SwiftShader) against `vite preview`.
 * Run: xvfb-run -a npx tsx scripts/benchViewer.ts
 */
import { spawn } from 'node:child_process';
import { readdirSync, readFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { chromium } from 'playwright-core';
import { defaultCatalog } from '../src/catalog/defaultCatalog';
import { createConfiguration } from '../src/model/configuration';
import { parsePhotometry } from '../src/photometry/parsePhotometry';
import type { Photometry } from '../src/photometry/types';
import { toLightingScene } from '../src/model/toLightingScene';
import { createHeadlessGL } from '../src/node/createHeadlessGL';
import { PUBLIC_DIR } from '../src/node/renderInput';
import { createRelightEngine } from '../src/relight/createRelightEngine';
import { createConfiguratorStore } from '../src/store/createConfiguratorStore';
import { chromiumArgs } from '../playwright.config';

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

function presetScene(presetId: string) {
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
  if (!store.getState().dispatch('placePreset', { presetId }).ok) throw new Error(`cannot place ${presetId}`);
  const scene = toLightingScene(store.getState().config, defaultCatalog);
  const parsed = new Map<string, Photometry>();
  const luminaires = scene.luminaires.map((l) => {
    if (!parsed.has(l.photometry)) parsed.set(l.photometry, parsePhotometry(readFileSync(PUBLIC_DIR + l.photometry), l.photometry));
    return { ...l, photometry: parsed.get(l.photometry)!, dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] as [number, number, number] };
  });
  return { room: scene.room, luminaires };
}

function relightVsRebake(presetId: string) {
  const scene = presetScene(presetId);
  const gl = createHeadlessGL();
  try {
    const t0 = performance.now();
    const engine = createRelightEngine(gl);
    engine.setScene(scene);
    engine.finish();
    engine.maps();
    const rebake = performance.now() - t0;
    const relights: number[] = [];
    for (let k = 0; k < 15; k++) {
      const dimmed = { ...scene, luminaires: scene.luminaires.map((l, i) => (i === 0 ? { ...l, dimming: 0.1 + 0.05 * k } : l)) };
      const s = performance.now();
      engine.setScene(dimmed);
      engine.maps();
      relights.push(performance.now() - s);
    }
    const texels = Object.values(engine.maps().layouts).reduce((n, l) => n + l.width * l.height, 0);
    engine.dispose();
    return { presetId, modules: scene.luminaires.length, texels, rebake, relight: median(relights) };
  } finally {
    gl.destroy();
  }
}

function bundleSizes() {
  const html = readFileSync('dist/index.html', 'utf8');
  const entry = /src="\/?(assets\/[^"]+\.js)"/.exec(html)?.[1];
  if (!entry) throw new Error('dist/index.html has no entry script: run npx vite build');
  const gz = (f: string) => gzipSync(readFileSync(join('dist', f)), { level: 9 }).length;
  const chunk = readdirSync('dist/assets').find((f) => /^View3D-.*\.js$/.test(f));
  return { entry: gz(entry), entryRaw: readFileSync(join('dist', entry)).length, view3d: chunk ? gz(`assets/${chunk}`) : NaN, view3dRaw: chunk ? readFileSync(join('dist/assets', chunk)).length : NaN };
}

async function toggleToFirstLit(): Promise<{ firstLit: number; done: number }[]> {
  const server = spawn('npx', ['vite', 'preview', '--port', '4178', '--strictPort'], { stdio: 'ignore', detached: true });
  try {
    await new Promise((r) => setTimeout(r, 2500));
    const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: chromiumArgs });
    const runs = [];
    for (let k = 0; k < 3; k++) {
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
      await page.goto('http://localhost:4178/');
      await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'corner-l' }));
      const t0 = Date.now();
      await page.getByTestId('tool-3d').click();
      await page.waitForFunction(() => (window.luxbox!.view3d() as { lit: boolean }).lit, null, { timeout: 120_000, polling: 20 });
      const firstLit = Date.now() - t0;
      await page.waitForFunction(() => (window.luxbox!.view3d() as { done: boolean }).done, null, { timeout: 120_000, polling: 50 });
      runs.push({ firstLit, done: Date.now() - t0 });
      await page.close();
    }
    await browser.close();
    return runs;
  } finally {
    if (server.pid) process.kill(-server.pid);
  }
}

const results = { relight: ['single', 'corner-l', 'snake'].map(relightVsRebake), bundles: bundleSizes(), chromium: await toggleToFirstLit() };
for (const r of results.relight) {
  console.log(`${r.presetId}: ${r.modules} modules, ${r.texels} texels/basis; full rebake ${r.rebake.toFixed(0)} ms, relight ${r.relight.toFixed(2)} ms, ratio ${(r.rebake / r.relight).toFixed(0)}×`);
}
const b = results.bundles;
console.log(`bundles: planner entry ${(b.entry / 1024).toFixed(1)} KiB gzip (${(b.entryRaw / 1024).toFixed(0)} KiB raw), 3D chunk ${(b.view3d / 1024).toFixed(1)} KiB gzip (${(b.view3dRaw / 1024).toFixed(0)} KiB raw)`);
console.log(`chromium toggle → first lit frame: ${results.chromium.map((r) => r.firstLit).join(', ')} ms; → bake done: ${results.chromium.map((r) => r.done).join(', ')} ms`);
