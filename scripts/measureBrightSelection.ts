/**
 * The bright-patch selection on the CPU (tile sums read back, selectBrightPatches.ts; the setting
 * brightSelection 'cpu') against the GPU (selectBrightPatchesOnGpu.ts, no read-back; the default),
 * docs/baker.md "Bright patches selected on the GPU". Per scene, on one warm context, the two
 * interleaved (so load changes hit both alike), `rounds` bakes each after one untimed warm-up of
 * each: the start of a bake (inputs, direct passes, the bright-patch pass, up to the first bounce)
 * and the whole bake without map output (run + finalize), each followed by gl.finish(); medians.
 * Also the read-backs each bake made before its report (readBackCounter.ts). Run:
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
console.log(`settings ${JSON.stringify(settings)}, median of ${rounds}`);
console.log('| scene | patches | start: CPU selection | start: GPU selection | GPU / CPU | bake: CPU selection | bake: GPU selection | GPU / CPU | read-backs before the report (CPU / GPU) |');
console.log('|---|---|---|---|---|---|---|---|---|');
for (const name of scenes) {
  const scene = loadRenderInput(join(import.meta.dirname, `../tests/fixtures/bench/${name}.json`)).bakeScene;
  const one = (brightSelection: 'cpu' | 'gpu') => {
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
  const cpu: ReturnType<typeof one>[] = [];
  const gpu: ReturnType<typeof one>[] = [];
  for (let r = 0; r < rounds; r++) {
    cpu.push(one('cpu'));
    gpu.push(one('gpu'));
  }
  const m = (xs: ReturnType<typeof one>[], k: 'start' | 'bake') => median(xs.map((x) => x[k]));
  const ms = (x: number) => `${x.toFixed(0)} ms`;
  console.log(
    `| ${name} | ${cpu[0].patches} / ${gpu[0].patches} | ${ms(m(cpu, 'start'))} | ${ms(m(gpu, 'start'))} | ${(m(gpu, 'start') / m(cpu, 'start')).toFixed(2)} | ${ms(m(cpu, 'bake'))} | ${ms(m(gpu, 'bake'))} | ${(m(gpu, 'bake') / m(cpu, 'bake')).toFixed(2)} | ${cpu[0].reads} / ${gpu[0].reads} |`,
  );
}
baker.dispose();
gl.destroy();
