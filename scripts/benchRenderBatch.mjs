#!/usr/bin/env node
// Shop-image batch benchmark (docs/benchmarks.md, "Shop images"): 50 product images with one command,
// `luxbox render` over 10 configurations (the corner-l system at five dimming levels, in 3000 K and
// 4000 K) × 5 cameras at a fixed EV100, against separate `luxbox render` processes for single images.
// Prints time per image and the programs linked; not a CI test (times depend on the machine).
//
//   node scripts/benchRenderBatch.mjs [--width 960 --height 600 --ev 5.5 --singles 3]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const args = process.argv.slice(2);
const opt = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const width = opt('--width', '960');
const height = opt('--height', '600');
const ev = opt('--ev', '5.5');
const singles = Number(opt('--singles', '3'));
const root = new URL('..', import.meta.url).pathname;
const dir = mkdtempSync(join(tmpdir(), 'luxbox-bench-batch-'));

const base = JSON.parse(readFileSync(join(root, 'tests/fixtures/configurations/corner-l.luxbox.json'), 'utf8'));
const configs = [];
for (const cct of [3000, 4000]) {
  for (const dimming of [1, 0.75, 0.5, 0.25, 0.1]) {
    const data = structuredClone(base);
    for (const system of data.configuration.systems) for (const rail of system.rails) for (const m of rail.modules) Object.assign(m, { dimming, cct });
    const file = join(dir, `corner-l-${cct}K-${Math.round(dimming * 100)}.luxbox.json`);
    writeFileSync(file, JSON.stringify(data));
    configs.push(file);
  }
}
const cameras = join(dir, 'cameras.json');
writeFileSync(
  cameras,
  JSON.stringify({
    eye: 'eye',
    top: 'top',
    corner: 'corner',
    rail: { position: [0.6, 1.4, 3.7], target: [2.2, 2.0, 2.2], fov: 55 },
    floor: { position: [4.6, 1.9, 3.8], target: [2.0, 0.0, 1.6], fov: 60 },
  }),
);

function luxbox(argv) {
  const t0 = performance.now();
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), 'render', ...argv], { cwd: root, encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`luxbox render failed (${r.status}): ${r.stderr}`);
  return performance.now() - t0;
}

const out = join(dir, 'images');
const batchMs = luxbox([...configs, '--cameras', cameras, '--ev', ev, '--width', width, '--height', height, '--out', `${out}/`]);
const summary = JSON.parse(readFileSync(join(out, 'summary.json'), 'utf8'));
const images = summary.images.length;
const bakeMs = summary.images.reduce((s, i) => s + i.bake_ms, 0);
const renderMs = summary.images.reduce((s, i) => s + i.render_ms, 0);
const singleMs = [];
for (let k = 0; k < singles; k++) singleMs.push(luxbox([configs[k], '--camera', 'eye', '--ev', ev, '--width', width, '--height', height, '--out', join(dir, `single-${k}.png`)]));
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const result = {
  images,
  scenes: configs.length,
  cameras: summary.cameras.length,
  size: `${width}×${height}`,
  ev100: Number(ev),
  batch_s: batchMs / 1000,
  per_image_ms: batchMs / images,
  bake_ms_total: bakeMs,
  render_ms_per_image: renderMs / images,
  programs_linked: summary.programs_linked,
  programs_linked_after_scene: summary.programs_linked_after_scene.map((p) => p.baker + p.view),
  single_process_ms_median: singles > 0 ? median(singleMs) : null,
  output: out,
};
process.stdout.write(JSON.stringify(result, null, 2) + '\n');
