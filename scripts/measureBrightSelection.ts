/**
 * The bright-patch selection on the CPU (tile sums read back, selectBrightPatches.ts; the setting
 * brightSelection 'cpu') against the GPU (selectBrightPatchesOnGpu.ts, no read-back; the default on a hardware renderer),
 * docs/baker.md "Bright patches selected on the GPU". Per scene, on one warm context, the two
 * interleaved (so load changes hit both alike), `rounds` bakes each after one untimed warm-up of
 * each: the start of a bake (inputs, direct passes, the bright-patch pass, up to the first bounce)
 * and the whole bake without map output (run + finalize), each followed by gl.finish(); min and
 * median, and the median of the per-round ratios (a load change between rounds hits both alike).
 * Also the read-backs each bake made before its report (readBackCounter.ts), and those of one bake
 * with the setting unset: which path the default took on this renderer (softwareRenderer.ts). Run:
 *   xvfb-run -a npx tsx scripts/measureBrightSelection.ts [rounds]
 */
import { join } from 'node:path';
import type { BakeSettings } from '../src/engines/bake/bakeSettings';
import { createBaker } from '../src/engines/bake/createBaker';
import { readBacks } from '../src/engines/bake/readBackCounter';
import { machineInfo } from '../src/hosts/bench/machineInfo';
import { createHeadlessGL } from '../src/hosts/node/createHeadlessGL';
import { loadRenderInput } from '../src/hosts/node/renderInput';

const rounds = Number(process.argv[2] ?? 5);
const scenes = ['spot-wall', 'ceiling-uplight', 'uplight-corridor', 'living-room', 'cie-cube'];
const settings: Partial<BakeSettings> = { texelSize: 0.05, samples: 32, bounces: 3 };

const gl = createHeadlessGL();
const baker = createBaker(gl);
const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const info = machineInfo(gl);
console.log(`${new Date().toISOString()} ${JSON.stringify(info)}`);
console.log(`settings ${JSON.stringify(settings)}, ${rounds} rounds, each CPU then GPU then unset; min / median, and the median of the per-round ratios GPU / CPU`);
console.log('| scene | patches (CPU / GPU) | start: CPU | start: GPU | start GPU / CPU | bake: CPU | bake: GPU | bake GPU / CPU | read-backs before the report (CPU / GPU / unset) |');
console.log('|---|---|---|---|---|---|---|---|---|');
type Run = { start: number; bake: number; reads: number; patches: number };
for (const name of scenes) {
  const scene = loadRenderInput(join(import.meta.dirname, `../tests/fixtures/bench/${name}.json`)).bakeScene;
  const one = (brightSelection: 'cpu' | 'gpu' | undefined): Run => {
    const before = readBacks(gl).count;
    const t0 = performance.now();
    const job = baker.start(scene, { ...settings, brightSelection });
    gl.finish();
    const t1 = performance.now();
    job.run();
    job.finalize();
    gl.finish();
    const t2 = performance.now();
    const reads = readBacks(gl).count - before;
    const patches = job.report().brightPatches?.count ?? 0;
    job.dispose();
    return { start: t1 - t0, bake: t2 - t0, reads, patches };
  };
  one('cpu');
  one('gpu');
  // Unset: the default, which path it takes shows in its read-backs (1: the CPU's tile sums).
  const unset = one(undefined);
  const cpu: Run[] = [];
  const gpu: Run[] = [];
  for (let r = 0; r < rounds; r++) {
    cpu.push(one('cpu'));
    gpu.push(one('gpu'));
  }
  const ms = (xs: Run[], k: 'start' | 'bake') => `${Math.min(...xs.map((x) => x[k])).toFixed(0)} / ${median(xs.map((x) => x[k])).toFixed(0)} ms`;
  const ratio = (k: 'start' | 'bake') => median(gpu.map((g, r) => g[k] / cpu[r][k])).toFixed(2);
  console.log(
    `| ${name} | ${cpu[0].patches} / ${gpu[0].patches} | ${ms(cpu, 'start')} | ${ms(gpu, 'start')} | ${ratio('start')} | ${ms(cpu, 'bake')} | ${ms(gpu, 'bake')} | ${ratio('bake')} | ${cpu[0].reads} / ${gpu[0].reads} / ${unset.reads} |`,
  );
}
baker.dispose();
gl.destroy();
