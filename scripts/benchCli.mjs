// CLI-level benchmark of issue 17 on the machine at hand (not run in CI):
//  1. GL back ends: one cold `luxbox bake` process per back end (DISPLAY unset, so
//     GLX pays for starting Xvfb as a real headless run does), and warm bakes in one
//     process — the measurement behind `--gl auto`'s choice on CPU-only machines.
//  2. Batches: the five bench scenes in one `luxbox bake a b c d e` process against
//     five separate processes (shader compiles and start-up paid once).
// Writes its section of docs/benchmarks.md (between its markers) and prints it.
// Usage: node scripts/benchCli.mjs [--repeats N]
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { cpus, tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

const root = resolve(new URL('..', import.meta.url).pathname);
const repeats = Number(process.argv[process.argv.indexOf('--repeats') + 1]) || 3;
const tmp = mkdtempSync(join(tmpdir(), 'luxbox-benchcli-'));
const env = { ...process.env };
delete env.DISPLAY;
delete env.LUXBOX_GL;

function timeCli(args) {
  const t0 = performance.now();
  const r = spawnSync(process.execPath, [join(root, 'bin/luxbox.js'), ...args], { cwd: root, env, encoding: 'utf8' });
  const ms = performance.now() - t0;
  if (r.status !== 0) throw new Error(`luxbox ${args.join(' ')} failed: ${r.stderr}`);
  return ms;
}
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const fmt = (ms) => (ms / 1000).toFixed(2);

const small = 'tests/fixtures/scenes/small-room.json';
const living = 'tests/fixtures/bench/living-room.json';
const backendRows = [];
for (const [label, scene, quality] of [
  ['small room, default quality', small, []],
  ['living room (10 lamps), 0.05 m / 64 samples / 4 bounces', living, ['--texel', '0.05']],
]) {
  const row = { label };
  for (const gl of ['glx', 'vulkan']) {
    const cold = [];
    for (let i = 0; i < repeats; i++) cold.push(timeCli(['bake', scene, '--out', join(tmp, `${gl}-${i}`), '--gl', gl, ...quality]));
    // Warm: the same scene three times in one process; the last bake's own timing.
    timeCli(['bake', scene, scene, scene, '--out', join(tmp, `${gl}-warm`), '--gl', gl, ...quality]);
    const stem = scene
      .split('/')
      .pop()
      .replace(/\.json$/, '');
    const warm = JSON.parse(readFileSync(join(tmp, `${gl}-warm`, `${stem}-3`, 'report.json'), 'utf8')).timings_ms.total;
    row[gl] = { cold: median(cold), warm };
  }
  backendRows.push(row);
}

const five = ['cie-cube', 'living-room', 'corridor', 'spot-wall', 'ceiling-uplight'].map((n) => `tests/fixtures/bench/${n}.json`);
const batchRows = [];
for (const gl of ['glx', 'vulkan']) {
  const separate = [];
  const batch = [];
  for (let i = 0; i < repeats; i++) {
    separate.push(five.reduce((sum, s, k) => sum + timeCli(['bake', s, '--out', join(tmp, `sep-${gl}-${i}-${k}`), '--gl', gl]), 0));
    batch.push(timeCli(['bake', ...five, '--out', join(tmp, `batch-${gl}-${i}`), '--gl', gl]));
  }
  batchRows.push({ gl, separate: median(separate), batch: median(batch) });
}

const date = new Date().toISOString().slice(0, 10);
const section = `## Command line: GL back ends and batches (\`node scripts/benchCli.mjs\`)

Machine: ${cpus().length} × ${cpus()[0]?.model ?? 'CPU'}, no GPU (Mesa llvmpipe for GLX under Xvfb, lavapipe for Vulkan), ${date}; wall time of whole \`luxbox\` processes with DISPLAY unset (GLX re-runs itself under \`xvfb-run\`), median of ${repeats}.

| scene | GLX cold process s | Vulkan cold process s | GLX warm bake s | Vulkan warm bake s |
|---|---:|---:|---:|---:|
${backendRows.map((r) => `| ${r.label} | ${fmt(r.glx.cold)} | ${fmt(r.vulkan.cold)} | ${fmt(r.glx.warm)} | ${fmt(r.vulkan.warm)} |`).join('\n')}

Five bench scenes (${five.map((f) => f.split('/').pop()).join(', ')}), default quality:

| back end | five processes s | one batch process s | batch / separate |
|---|---:|---:|---:|
${batchRows.map((r) => `| ${r.gl} | ${fmt(r.separate)} | ${fmt(r.batch)} | ${(r.batch / r.separate).toFixed(2)} |`).join('\n')}
`;
const markers = ['<!-- luxbox bench cli: start (generated) -->', '<!-- luxbox bench cli: end -->'];
const docPath = join(root, 'docs/benchmarks.md');
const doc = readFileSync(docPath, 'utf8');
const block = `${markers[0]}\n${section.trim()}\n${markers[1]}\n`;
const s = doc.indexOf(markers[0]);
const e = doc.indexOf(markers[1]);
writeFileSync(docPath, s >= 0 && e > s ? doc.slice(0, s) + block + doc.slice(e + markers[1].length).replace(/^\n/, '') : doc.replace(/\s*$/, '\n\n') + block);
console.log(section);
