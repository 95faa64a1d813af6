import { existsSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { benchTables, spliceSection } from '../bench/benchMarkdown';
import { BENCH_DOC_INTRO, BENCH_DOC_OUTRO, BENCH_MARKERS } from '../bench/benchDocText';
import { errorTimeSvg } from '../bench/errorTimeSvg';
import { directSourcesExperiment, drawOverheadMs, gpuBenchTable, profileLookupExperiment, runGpuBench, statsRecordMs } from '../bench/gpuBench';
import { runBench } from '../bench/runBench';
import { DAYLIGHT_MARKERS, daylightSection, runDaylightBench } from '../bench/daylightBench';
import { machineInfo } from '../bench/machineInfo';
import { createBaker } from '../../engines/bake/createBaker';
import { createHeadlessGL } from '../node/createHeadlessGL';
import { peerTables, runRadiancePeerBench } from '../bench/radianceBench';
import { RADIANCE_DOC_INTRO, RADIANCE_MARKERS } from '../bench/radianceDocText';
import { InputError } from '../../core/inputError';
import { prepareGl } from '../node/prepareGl';

const usage = 'bench [--quick] [--out <dir>] [--gl vulkan|glx|auto] | bench --gpu [--repeats N] [--gl …] | bench --radiance [--out <dir>] | bench --daylight [--out <dir>]';
const SVG = 'benchmarks-error-vs-time.svg';

interface BenchArgs {
  quick: boolean;
  out: string | null;
  gl: string | undefined;
  gpu: boolean;
  radiance: boolean;
  daylight: boolean;
  repeats: number;
}

function parseBenchArgs(args: string[]): BenchArgs {
  const b: BenchArgs = { quick: false, out: null, gl: undefined, gpu: false, radiance: false, daylight: false, repeats: 10 };
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    if (a === '--quick') b.quick = true;
    else if (a === '--gpu') b.gpu = true;
    else if (a === '--radiance') b.radiance = true;
    else if (a === '--daylight') b.daylight = true;
    else if (a === '--repeats') {
      b.repeats = Number(args[++i]);
      if (!Number.isInteger(b.repeats) || b.repeats < 1 || b.repeats > 1000) throw new InputError(`--repeats must be an integer in 1..1000 (usage: luxbox ${usage})`);
    } else if (a === '--out') {
      b.out = args[++i] ?? null;
      if (!b.out) throw new InputError(`--out needs a folder (usage: luxbox ${usage})`);
    } else if (a === '--gl') {
      b.gl = args[++i];
      if (!b.gl) throw new InputError(`--gl needs vulkan, glx or auto (usage: luxbox ${usage})`);
    } else throw new InputError(`unknown argument "${a}" (usage: luxbox ${usage})`);
  }
  return b;
}

/**
 * `luxbox bench`: error against run time of the GPU baker on the named scenes,
 * and bake time against luminaires and texels. The full run writes its section
 * of docs/benchmarks.md and the SVG plot (or into --out); `--quick`
 * is a smoke run that prints its tables and writes files only with --out.
 */
export async function run(args: string[]): Promise<number> {
  const parsed = parseBenchArgs(args);
  const { quick, gl, gpu, radiance, daylight, repeats } = parsed;
  let out = parsed.out;
  const { exit, backend } = prepareGl(gl);
  if (exit !== null) return exit;
  if (gpu) {
    // Bundled (docs/gpu-server.md) the module URL is the bundle's: scenes are read from the working folder.
    const rows = runGpuBench(process.cwd(), repeats, (line) => process.stderr.write(line + '\n'));
    const perDraw = drawOverheadMs();
    process.stdout.write(
      `GL back end: ${backend}\n\n${gpuBenchTable(rows)}\n\nOne 256² combine draw in a stream of 200 (per-draw cost): ${perDraw.toFixed(3)} ms\nOne flux-statistics record (living room, 0.05 m): ${statsRecordMs().toFixed(3)} ms\n`,
    );
    for (const r of profileLookupExperiment(process.cwd(), repeats))
      process.stdout.write(`Profile lookup, ${r.case}: measured grid ${r.measuredMs.toFixed(2)} ms, dense ${r.denseMs.toFixed(2)} ms, ratio ${(r.denseMs / r.measuredMs).toFixed(3)}\n`);
    const x = directSourcesExperiment(process.cwd(), repeats);
    process.stdout.write(
      `Direct pass, 20 lamps, 6 × 256², centres: source positions in const arrays ${x.constArrays.toFixed(2)} ms, in uniform arrays ${x.uniformArrays.toFixed(2)} ms (largest relative difference ${x.maxError.toExponential(1)})\n`,
    );
    return 0;
  }
  const root = resolve(fileURLToPath(new URL('../../..', import.meta.url)));
  if (!quick && out === null) out = join(root, 'docs');
  if (radiance) {
    const tables = peerTables(runRadiancePeerBench(root, (line) => process.stderr.write(line + '\n')));
    const docPath = join(out ?? join(root, 'docs'), 'benchmarks.md');
    mkdirSync(dirname(docPath), { recursive: true });
    const doc = existsSync(docPath) ? readFileSync(docPath, 'utf8') : '';
    writeFileSync(docPath, spliceSection(doc, `${RADIANCE_DOC_INTRO}\n${tables}\n`, RADIANCE_MARKERS));
    process.stdout.write(tables + `\n\nwrote ${docPath}\n`);
    return 0;
  }
  if (daylight) {
    const docPath = join(out ?? join(root, 'docs'), 'benchmarks.md');
    const section = daylightBenchSection((line) => process.stderr.write(line + '\n'));
    mkdirSync(dirname(docPath), { recursive: true });
    const doc = existsSync(docPath) ? readFileSync(docPath, 'utf8') : '';
    writeFileSync(docPath, spliceSection(doc, section, DAYLIGHT_MARKERS));
    process.stdout.write(section + `\nwrote ${docPath}\n`);
    return 0;
  }
  const result = runBench({ quick, root, log: (line) => process.stderr.write(line + '\n') });
  const tables = benchTables(result, out ? SVG : null);
  if (out) {
    mkdirSync(out, { recursive: true });
    const series = [...new Set(result.rows.map((r) => r.scene))].map((scene) => {
      const rows = result.rows.filter((r) => r.scene === scene);
      return {
        label: scene,
        rms: rows.map((r) => [r.bakeMs / 1000, r.total.rms] as [number, number]),
        max: rows.map((r) => [r.bakeMs / 1000, r.total.max] as [number, number]),
      };
    });
    writeFileSync(join(out, SVG), errorTimeSvg(series, `GPU bake vs converged reference (${result.machine.date.slice(0, 10)})`));
    // docs/benchmarks.md has other sections (viewer): replace only ours.
    const docPath = join(out, 'benchmarks.md');
    const doc = existsSync(docPath) ? readFileSync(docPath, 'utf8') : '';
    writeFileSync(docPath, spliceSection(doc, `${BENCH_DOC_INTRO}\n${tables}\n${BENCH_DOC_OUTRO}`, BENCH_MARKERS));
    process.stderr.write(`wrote ${docPath} and ${join(out, SVG)}\n`);
  }
  process.stdout.write(tables + '\n');
  return 0;
}

/** The daylit rooms alone (daylightBench.ts) on a fresh context: docs/benchmarks.md's daylight section. */
function daylightBenchSection(log: (line: string) => void): string {
  const gl = createHeadlessGL();
  try {
    const machine = machineInfo(gl);
    return daylightSection(runDaylightBench(createBaker(gl), log), machine);
  } finally {
    gl.destroy();
  }
}
