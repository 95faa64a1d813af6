/**
 * Viewer benchmarks (docs/benchmarks.md, "Viewer" and "3D lifecycle"): relight vs full rebake
 * (headless-gl, same run), relight per frame on the CPU vs the GPU combine (scripts/bench/benchGpuRelight.ts), bake cost against module count (scripts/bench/benchModuleCount.ts),
 * time to first lit frame and to done per quality level with the device calibration
 * (scripts/bench/benchQualityLevels.ts), gzip sizes of the planner entry bundle and the 3D
 * chunk (from dist/, run `npx vite build` first), and in Chromium (SwiftShader) against
 * `vite preview`: toggle → first lit frame, then 3D → 2D → 3D with no change (first lit frame
 * of the second opening and the bakes it started). Part of `npm run bench`.
 * Run alone: npx vite build && xvfb-run -a npx tsx scripts/benchViewer.ts [results.json]
 */
import { spawn } from 'node:child_process';
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { gzipSync } from 'node:zlib';
import { chromium, type Page } from 'playwright-core';
import { defaultCatalog } from '../src/core/catalog/defaultCatalog';
import { createConfiguration } from '../src/core/model/configuration/configuration';
import { parsePhotometry } from '../src/core/photometry/parsePhotometry';
import type { Photometry } from '../src/core/photometry/types';
import { toLightingScene } from '../src/core/model/files/toLightingScene';
import { createHeadlessGL } from '../src/hosts/node/createHeadlessGL';
import { PUBLIC_DIR } from '../src/hosts/node/renderInput';
import { createRelightEngine } from '../src/engines/relight/createRelightEngine';
import { createConfiguratorStore } from '../src/core/store/createConfiguratorStore';
import { chromiumArgs } from '../playwright.config';
import { benchGpuRelight } from './bench/benchGpuRelight';
import { benchModuleCount } from './bench/benchModuleCount';
import { benchQualityLevels } from './bench/benchQualityLevels';
import { machineInfo } from '../src/hosts/bench/machineInfo';
import type { ViewerStatus } from '../src/ui/viewer/viewerStatus';

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

function presetScene(presetId: string) {
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
  if (!store.getState().dispatch('placePreset', { presetId }).ok) throw new Error(`cannot place ${presetId}`);
  const scene = toLightingScene(store.getState().config, defaultCatalog);
  const parsed = new Map<string, Photometry>();
  const luminaires = scene.luminaires.map((l) => {
    if (!parsed.has(l.photometry)) parsed.set(l.photometry, parsePhotometry(readFileSync(PUBLIC_DIR + l.photometry), l.photometry));
    return { ...l, photometry: parsed.get(l.photometry)!, dimming: l.dimming ?? 1, color: l.color ?? ([1, 1, 1] as [number, number, number]) };
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

interface ManifestChunk {
  file: string;
  isEntry?: boolean;
  src?: string;
  imports?: string[];
  css?: string[];
}

/**
 * What the browser downloads: the app page's entry with every chunk it
 * statically imports (preloaded) and their CSS; the 3D view is everything the
 * lazy View3D chunk adds on top. Sizes are gzip -9 per file, summed, as a
 * server would send them. Read from Vite's manifest (build.manifest).
 */
function bundleSizes() {
  const manifest = JSON.parse(readFileSync('dist/.vite/manifest.json', 'utf8')) as Record<string, ManifestChunk>;
  const closure = (key: string, seen = new Set<string>()): Set<string> => {
    if (seen.has(key)) return seen;
    seen.add(key);
    for (const dep of manifest[key]?.imports ?? []) closure(dep, seen);
    return seen;
  };
  const files = (keys: Iterable<string>) => new Set([...keys].flatMap((k) => [manifest[k].file, ...(manifest[k].css ?? [])]));
  const gz = (f: string) => gzipSync(readFileSync(join('dist', f)), { level: 9 }).length;
  const raw = (f: string) => readFileSync(join('dist', f)).length;
  const sum = (set: Set<string>, size: (f: string) => number) => [...set].reduce((t, f) => t + size(f), 0);
  const initial = files(closure('index.html'));
  const viewKey = Object.keys(manifest).find((k) => /View3D\.tsx$/.test(k));
  if (!viewKey) throw new Error('no View3D chunk in dist/.vite/manifest.json: run npx vite build');
  const view = new Set([...files(closure(viewKey))].filter((f) => !initial.has(f)));
  return { entry: sum(initial, gz), entryRaw: sum(initial, raw), view3d: sum(view, gz), view3dRaw: sum(view, raw) };
}

interface ToggleRun {
  /** Click on the 3D toggle right after placing the preset → first lit frame, ms (chunk, photometry, direct bases included). */
  firstLit: number;
  /** → progressive bake done, ms. */
  done: number;
  /** 3D → 2D → 3D with no change: click → first lit frame of the second opening, ms. */
  secondFirstLit: number;
  /** Which frame of the second opening was the first lit one (1: it opened on finished light). */
  secondFirstLitFrame: number | null;
  /** Bake service counters (group bakes + indirect solves) before the second opening and after it is lit. */
  bakesBefore: number;
  bakesAfter: number;
}

async function toggleToFirstLit(): Promise<ToggleRun[]> {
  const server = spawn('npx', ['vite', 'preview', '--port', '4178', '--strictPort'], { stdio: 'ignore', detached: true });
  try {
    await new Promise((r) => setTimeout(r, 2500));
    const browser = await chromium.launch({ executablePath: '/usr/bin/chromium', args: chromiumArgs });
    const runs: ToggleRun[] = [];
    const status = (page: Page) => page.evaluate(() => window.luxbox!.view3d() as ViewerStatus);
    const bakes = (s: ViewerStatus) => s.bake.groupBakes + s.bake.indirectSolves;
    for (let k = 0; k < 3; k++) {
      const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
      // Quality pinned to 'balanced' so the figures do not depend on this machine's calibration.
      await page.goto('http://localhost:4178/?quality=balanced');
      await page.evaluate(() => window.luxbox!.runAction('placePreset', { presetId: 'corner-l' }));
      const t0 = Date.now();
      await page.getByTestId('tool-3d').click();
      await page.waitForFunction(() => (window.luxbox!.view3d() as ViewerStatus).lit, null, { timeout: 120_000, polling: 20 });
      const firstLit = Date.now() - t0;
      await page.waitForFunction(() => (window.luxbox!.view3d() as ViewerStatus).done, null, { timeout: 120_000, polling: 50 });
      const done = Date.now() - t0;
      // Back to the plan, nothing changed, and into 3D again.
      await page.getByTestId('tool-3d').click();
      await page.waitForFunction(() => !(window.luxbox!.view3d() as ViewerStatus).open, null, { timeout: 30_000, polling: 20 });
      await page.waitForTimeout(500);
      const bakesBefore = bakes(await status(page));
      const t1 = Date.now();
      await page.getByTestId('tool-3d').click();
      await page.waitForFunction(
        () => {
          const s = window.luxbox!.view3d() as ViewerStatus;
          return s.open && s.lit;
        },
        null,
        { timeout: 120_000, polling: 10 },
      );
      const secondFirstLit = Date.now() - t1;
      const after = await status(page);
      runs.push({ firstLit, done, secondFirstLit, secondFirstLitFrame: after.firstLitFrame, bakesBefore, bakesAfter: bakes(after) });
      await page.close();
    }
    await browser.close();
    return runs;
  } finally {
    if (server.pid) process.kill(-server.pid);
  }
}

const log = (line: string) => console.log(line);
const machineGl = createHeadlessGL();
const machine = machineInfo(machineGl);
machineGl.destroy();
log(`machine: ${machine.cpuModel}, ${machine.cores} cores, ${machine.memoryGiB} GiB; GL: ${machine.glRenderer}; ${machine.date}`);
const relight = ['single', 'corner-l', 'snake'].map(relightVsRebake);
for (const r of relight) {
  log(`${r.presetId}: ${r.modules} modules, ${r.texels} texels/basis; full rebake ${r.rebake.toFixed(0)} ms, relight ${r.relight.toFixed(2)} ms, ratio ${(r.rebake / r.relight).toFixed(0)}×`);
}
const gpuRelight = benchGpuRelight();
log(
  `relight per frame, ${gpuRelight.modules} modules (${gpuRelight.texels} texels/basis): CPU ${gpuRelight.cpuMs.toFixed(2)} ms (+ upload to the view ${gpuRelight.cpuUploadMs.toFixed(2)} ms), ` +
    `GPU combine ${gpuRelight.gpuMs.float.toFixed(2)} ms (RGBA32F bases, ${gpuRelight.textureMiB.float.toFixed(1)} MiB) / ${gpuRelight.gpuMs.half.toFixed(2)} ms (RGBA16F, ${gpuRelight.textureMiB.half.toFixed(1)} MiB); ` +
    `ratio CPU+upload / GPU ${(gpuRelight.cpuUploadMs / gpuRelight.gpuMs.float).toFixed(2)}×; read-backs ${gpuRelight.readbacks}`,
);
log(
  `view frame (relight + floor statistics): today ${gpuRelight.cpuViewMs.toFixed(2)} ms (maps read back ${gpuRelight.perFrame.cpu.mapReadbacks}, uploaded ${gpuRelight.perFrame.cpu.uploadBytes} B), ` +
    `GPU ${gpuRelight.gpuViewMs.toFixed(2)} ms (maps read back ${gpuRelight.perFrame.gpu.mapReadbacks}, statistics ${gpuRelight.perFrame.gpu.readbackBytes} B, uploaded ${gpuRelight.perFrame.gpu.uploadBytes} B); ratio ${(gpuRelight.cpuViewMs / gpuRelight.gpuViewMs).toFixed(2)}×; ` +
    `the bases' one transfer into the view: ${(gpuRelight.transferBytes / 2 ** 20).toFixed(1)} MiB in ${gpuRelight.firstRelightMs.toFixed(0)} ms`,
);
log('bake cost against module count (8 × 6 × 2.8 m, balanced):');
const moduleCount = benchModuleCount(3, log);
const at = (n: number) => moduleCount.find((r) => r.modules === n)!;
for (const n of [11, 20]) log(`ratio ${n}:3 — lit ${(at(n).litMs / at(3).litMs).toFixed(2)}×, done ${(at(n).doneMs / at(3).doneMs).toFixed(2)}×`);
log('quality levels:');
const quality = benchQualityLevels(log);
const bundles = bundleSizes();
log(`bundles: planner entry ${(bundles.entry / 1024).toFixed(1)} KiB gzip (${(bundles.entryRaw / 1024).toFixed(0)} KiB raw), 3D chunk ${(bundles.view3d / 1024).toFixed(1)} KiB gzip (${(bundles.view3dRaw / 1024).toFixed(0)} KiB raw)`);
const toggles = await toggleToFirstLit();
log(`chromium toggle → first lit frame: ${toggles.map((r) => r.firstLit).join(', ')} ms; → bake done: ${toggles.map((r) => r.done).join(', ')} ms`);
log(
  `chromium 3D → 2D → 3D, no change: first lit frame ${toggles.map((r) => r.secondFirstLit).join(', ')} ms (first lit frame number ${toggles.map((r) => r.secondFirstLitFrame ?? '–').join(', ')}); bakes (group bakes + indirect solves) before → after: ${toggles.map((r) => `${r.bakesBefore} → ${r.bakesAfter}`).join(', ')}`,
);
if (process.argv[2]) writeFileSync(process.argv[2], JSON.stringify({ machine, relight, gpuRelight, moduleCount, quality, bundles, toggles }, null, 2));
