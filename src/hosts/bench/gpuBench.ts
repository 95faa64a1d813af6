/**
 * `luxbox bench --gpu`: the numbers issue 17 asks for on a GPU server
 * (docs/gpu-server.md, docs/benchmarks.md "GPU"): warm and cold bakes of a
 * living-room-class scene, a direct-only stress bake, and the share of a bake
 * spent reading maps back. Every timing includes the GPU wait (gl.finish or a
 * read-back), so queued work is never mistaken for done work.
 */
import { join } from 'node:path';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { BakeSettings } from '../../engines/bake/bakeSettings';
import { createBaker } from '../../engines/bake/createBaker';
import { SURFACE_NAMES, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { createHeadlessGL } from '../node/createHeadlessGL';
import { createFluxStatistics } from '../../engines/bake/fluxStatistics';
import { surfaceLayouts } from '../../engines/bake/surfaceLayout';
import { createTargetPool } from '../../engines/bake/targetPool';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { getProgram } from '../../engines/bake/glResources';
import { createFloatTarget, readRgba, requireFloatTargets, type FloatTarget } from '../../engines/bake/floatTarget';
import { createDataTexture } from '../../engines/bake/createDataTexture';
import { passProgram, runPass } from '../../engines/bake/runPass';
import type { UniformSpec } from '../../../shaders/fragmentPass.glsl';
import { resolveBakeSettings } from '../../engines/bake/bakeSettings';
import { buildProfileTable, DATA_TEXTURE_WIDTH } from '../../engines/bake/profileTable';
import { directUniforms, generateDirectShader, type DirectLamp } from '../../engines/bake/generateDirectShader';
import { lampReachesSurface } from '../../engines/bake/lampReach';
import { scenePointSources } from '../../engines/bake/scenePointSources';
import { loadLightingSceneFile } from '../node/loadLightingSceneFile';

export interface GpuBenchRow {
  case: string;
  description: string;
  /** First bake on a fresh context: shader compiles included. */
  coldMs: number;
  /** Median and spread of the warm repeats. */
  warmMedianMs: number;
  warmMinMs: number;
  warmMaxMs: number;
  repeats: number;
  /** Warm bake whose maps are then read back (what the CLI does), median. */
  withReadbackMs: number | null;
  readbackShare: number | null;
  texels: number;
  pointSources: number;
  /** One warm bake with syncTimings (a finish after every pass), ms per pass; "other" = allocation, uploads, JS. */
  breakdown: Record<string, number>;
}

function median(xs: number[]): number {
  const s = [...xs].sort((a, b) => a - b);
  return s.length % 2 ? s[(s.length - 1) / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
}

/** Six lamps of the bench living room (four downlights, the pendant, a track spot): the "hidden-room class" of the issue. */
function livingRoomSix(root: string): BakeScene {
  const loaded = loadLightingSceneFile(join(root, 'tests/fixtures/bench/living-room.json'));
  return { ...loaded.bakeScene, luminaires: loaded.bakeScene.luminaires.slice(0, 6) };
}

/** A 12.8 m cube at 0.05 m texels: every surface 256², lit by 20 real lamps (ceiling grid, mixed photometry). */
function directStress(root: string): BakeScene {
  const loaded = loadLightingSceneFile(join(root, 'tests/fixtures/bench/living-room.json'));
  const kinds = loaded.bakeScene.luminaires;
  const luminaires = Array.from({ length: 20 }, (_, i) => {
    const k = kinds[i % kinds.length];
    const x = 1.6 + (i % 5) * 2.4;
    const z = 2 + Math.floor(i / 5) * 2.9;
    return { ...k, position: [x, 12.0, z] as [number, number, number] };
  });
  return { room: { width: 12.8, height: 12.8, depth: 12.8, reflectance: Object.fromEntries(SURFACE_NAMES.map((s) => [s, 0.5])) as Record<SurfaceName, number> }, luminaires };
}

export function runGpuBench(root: string, repeats: number, log: (line: string) => void): GpuBenchRow[] {
  const cases: { name: string; description: string; scene: BakeScene; settings: Partial<BakeSettings>; readback: boolean }[] = [
    { name: 'living-6', description: 'living room 5 × 4 × 2.7 m, 6 real lamps, 0.05 m, 256 samples, 4 bounces', scene: livingRoomSix(root), settings: { texelSize: 0.05, samples: 256, bounces: 4, samplesPerDraw: 256 }, readback: true },
    { name: 'direct-20', description: '6 × 256² texels, 20 real lamps, direct only', scene: directStress(root), settings: { texelSize: 0.05, bounces: 0, maxTextureSize: 256 }, readback: true },
    { name: 'direct-20-centre', description: 'as direct-20, texel centres only (texelSupersampling 1)', scene: directStress(root), settings: { texelSize: 0.05, bounces: 0, maxTextureSize: 256, texelSupersampling: 1 }, readback: false },
    { name: 'living-6-default', description: 'living room, 6 lamps, default settings (0.025 m, 64 samples, 4 bounces)', scene: livingRoomSix(root), settings: {}, readback: true },
  ];
  const rows: GpuBenchRow[] = [];
  for (const c of cases) {
    // A fresh context per case, so "cold" really compiles.
    const gl = createHeadlessGL();
    try {
      const baker = createBaker(gl);
      const once = (read: boolean) => {
        const t0 = performance.now();
        const job = baker.start(c.scene, c.settings);
        job.run();
        if (read) job.readMaps();
        else gl.finish();
        const ms = performance.now() - t0;
        const report = job.report();
        job.dispose();
        return { ms, report };
      };
      const cold = once(false);
      const cpu0 = process.cpuUsage();
      const wall0 = performance.now();
      const warm = Array.from({ length: repeats }, () => once(false).ms);
      const cpu = process.cpuUsage(cpu0);
      const cpuShare = (cpu.user + cpu.system) / 1000 / (performance.now() - wall0);
      const sync = (() => {
        const job = baker.start(c.scene, { ...c.settings, syncTimings: true });
        job.run();
        gl.finish();
        const t = job.report().timings_ms;
        job.dispose();
        const parts = { compile: t.compile, direct: t.direct, indirect: t.indirect, blur: t.blur, blend: t.blend, readback: t.readback };
        const other = t.total - Object.values(parts).reduce((a, b) => a + b, 0);
        return { ...parts, other, total: t.total };
      })();
      const read = c.readback ? Array.from({ length: Math.max(3, Math.ceil(repeats / 2)) }, () => once(true).ms) : [];
      const row: GpuBenchRow = {
        case: c.name,
        description: c.description,
        coldMs: cold.ms,
        warmMedianMs: median(warm),
        warmMinMs: Math.min(...warm),
        warmMaxMs: Math.max(...warm),
        repeats,
        withReadbackMs: read.length ? median(read) : null,
        readbackShare: read.length ? Math.max(0, (median(read) - median(warm)) / median(read)) : null,
        texels: cold.report.totalTexels,
        pointSources: cold.report.pointSources,
        breakdown: sync,
      };
      log(`${c.name}: CPU time / wall time over the warm repeats ${cpuShare.toFixed(2)} (1 = CPU-bound, driver threads included)`);
      log(`${c.name}: cold ${row.coldMs.toFixed(1)} ms, warm median ${row.warmMedianMs.toFixed(2)} ms, with read-back ${row.withReadbackMs?.toFixed(2)} ms`);
      rows.push(row);
    } finally {
      gl.destroy();
    }
  }
  return rows;
}

/**
 * Cost of one small draw (a 256² combine pass) when nothing else happens:
 * 200 draws then one finish. Separates per-draw overhead (driver, ANGLE,
 * headless-gl's JS validation) from arithmetic in the bake timings.
 */
export function drawOverheadMs(): number {
  const gl = createHeadlessGL();
  try {
    requireFloatTargets(gl);
    const a = createFloatTarget(gl, 256, 256, false);
    const b = createFloatTarget(gl, 256, 256, false);
    const prog = passProgram(gl, combinePass);
    const draw = (out: FloatTarget, src: FloatTarget) => runPass(gl, prog, out, { uA: src.texture, uB: src.texture, uScaleA: [1, 1, 1], uScaleB: [0, 0, 0] });
    for (let i = 0; i < 20; i++) draw(i % 2 ? a : b, i % 2 ? b : a);
    gl.finish();
    const n = 200;
    const t0 = performance.now();
    for (let i = 0; i < n; i++) draw(i % 2 ? a : b, i % 2 ? b : a);
    gl.finish();
    return (performance.now() - t0) / n;
  } finally {
    gl.destroy();
  }
}

/** One flux-statistics record (six maps reduced, one stats texel written) on the living room's 0.05 m maps: 50 records, one finish. */
export function statsRecordMs(): number {
  const gl = createHeadlessGL();
  try {
    requireFloatTargets(gl);
    const room = { width: 5, height: 2.7, depth: 4 };
    const layouts = surfaceLayouts(room, 0.05, 512);
    const pool = createTargetPool(gl, false);
    const maps = layouts.map((l) => pool.acquire(l.width, l.height));
    const stats = createFluxStatistics(
      gl,
      pool,
      layouts,
      layouts.map(() => [0.5, 0.5, 0.5]),
      50,
      () => {},
    );
    stats.record(0, maps, 1);
    gl.finish();
    const t0 = performance.now();
    for (let i = 0; i < 50; i++) stats.record(i, maps, 1);
    gl.finish();
    const ms = (performance.now() - t0) / 50;
    stats.dispose();
    pool.dispose();
    return ms;
  } finally {
    gl.destroy();
  }
}

/**
 * Experiment behind the direct pass's cost: the 20-lamp direct-only scene's
 * six direct draws (texel centres), as generated (source positions in const
 * arrays) and with the positions moved to uniform arrays (a constant buffer
 * every thread reads at the same index). Median of `repeats`, ms per six draws.
 */
export function directSourcesExperiment(root: string, repeats: number): { constArrays: number; uniformArrays: number; maxError: number } {
  const gl = createHeadlessGL();
  try {
    const { linear } = requireFloatTargets(gl);
    const scene = directStress(root);
    const settings = resolveBakeSettings({ texelSize: 0.05, maxTextureSize: 256, texelSupersampling: 1 });
    const photometries = [...new Set(scene.luminaires.map((l) => l.photometry))];
    const table = buildProfileTable(photometries);
    const data = createDataTexture(gl, table.data, DATA_TEXTURE_WIDTH, table.rows);
    const lamps: DirectLamp[] = scenePointSources(scene, settings).map((l) => ({ profile: table.layouts[photometries.indexOf(l.photometry)], rotation: l.rotation, sources: l.sources, sides: l.sides, weight: l.weight }));
    const layouts = surfaceLayouts(scene.room, settings.texelSize, settings.maxTextureSize);
    const variants = layouts.map((layout) => {
      const reaching = lamps.filter((l) => lampReachesSurface(l.sources, l.rotation, l.profile.gammaMin, l.profile.gammaMax, layout));
      const { source } = generateDirectShader(layout, reaching, 1);
      const values: Float32Array[] = [];
      const uniformSource = source.replace(/const vec3 (LAMP\d+_SOURCES)\[(\d+)\] = vec3\[\d+\]\(([^;]*)\);/g, (_m, name: string, n: string, list: string) => {
        values.push(new Float32Array((list.replace(/vec3/g, '').match(/-?[\d.]+(?:e[-+]?\d+)?/g) ?? []).map(Number)));
        return `uniform vec3 ${name}[${n}];`;
      });
      const names = [...source.matchAll(/const vec3 (LAMP\d+_SOURCES)\[/g)].map((m) => m[1]);
      const uniformSpec: UniformSpec = { ...directUniforms, ...Object.fromEntries(names.map((name, i) => [name, `vec3[${values[i].length / 3}]` as const])) };
      const uniformValues = { uProfiles: data, ...Object.fromEntries(names.map((name, i) => [name, values[i]])) };
      return { layout, source, uniformSource, uniformSpec, uniformValues, target: createFloatTarget(gl, layout.width, layout.height, linear) };
    });
    const run = (uniform: boolean) => {
      for (const v of variants) {
        const program = getProgram(gl, uniform ? v.uniformSource : v.source).program;
        if (uniform) runPass(gl, { program, uniforms: v.uniformSpec }, v.target, v.uniformValues);
        else runPass(gl, { program, uniforms: directUniforms }, v.target, { uProfiles: data });
      }
      gl.finish();
    };
    const time = (uniform: boolean) => {
      run(uniform);
      return median(
        Array.from({ length: repeats }, () => {
          const t0 = performance.now();
          run(uniform);
          return performance.now() - t0;
        }),
      );
    };
    const constArrays = time(false);
    const a = variants.map((v) => readRgba(gl, v.target));
    const uniformArrays = time(true);
    const b = variants.map((v) => readRgba(gl, v.target));
    let maxError = 0;
    a.forEach((x, i) => x.forEach((value, j) => (maxError = Math.max(maxError, Math.abs(value - b[i][j]) / Math.max(Math.abs(value), 1e-6)))));
    return { constArrays, uniformArrays, maxError };
  } finally {
    gl.destroy();
  }
}

export function gpuBenchTable(rows: GpuBenchRow[]): string {
  const f = (x: number | null, d = 1) => (x === null ? '–' : x.toFixed(d));
  return [
    '| case | texels | point sources | cold ms | warm ms (median, min–max, n) | warm + read maps ms | read-back share |',
    '|---|---:|---:|---:|---|---:|---:|',
    ...rows.map(
      (r) =>
        `| ${r.case}: ${r.description} | ${r.texels} | ${r.pointSources} | ${f(r.coldMs)} | ${f(r.warmMedianMs, 2)} (${f(r.warmMinMs, 2)}–${f(r.warmMaxMs, 2)}, ${r.repeats}) | ${f(r.withReadbackMs, 2)} | ${r.readbackShare === null ? '–' : `${(r.readbackShare * 100).toFixed(0)} %`} |`,
    ),
    '',
    'Per pass, one warm bake with a GPU wait after every pass (ms):',
    '',
    '| case | ' + Object.keys(rows[0]?.breakdown ?? {}).join(' | ') + ' |',
    '|---|' +
      Object.keys(rows[0]?.breakdown ?? {})
        .map(() => '---:')
        .join('|') +
      '|',
    ...rows.map(
      (r) =>
        `| ${r.case} | ${Object.values(r.breakdown)
          .map((v) => v.toFixed(2))
          .join(' | ')} |`,
    ),
  ].join('\n');
}

/**
 * Dense profile tables against the measured grid's bin-table lookup (docs/baker.md, "Profile
 * table"): the 20-lamp direct-only scene (6 × 256², texel means and texel centres), both lookups
 * on one warm context, interleaved so load changes hit both alike. Median ms per bake (GPU waited).
 */
export function profileLookupExperiment(root: string, repeats: number): { case: string; measuredMs: number; denseMs: number }[] {
  const gl = createHeadlessGL();
  try {
    const baker = createBaker(gl);
    const scene = directStress(root);
    const cases: [string, Partial<BakeSettings>][] = [
      ['direct-20', { texelSize: 0.05, bounces: 0, maxTextureSize: 256 }],
      ['direct-20-centre', { texelSize: 0.05, bounces: 0, maxTextureSize: 256, texelSupersampling: 1 }],
    ];
    return cases.map(([name, settings]) => {
      const once = (profileLookup: 'dense' | 'measured') => {
        const t0 = performance.now();
        const job = baker.start(scene, { ...settings, profileLookup });
        job.run();
        gl.finish();
        const ms = performance.now() - t0;
        job.dispose();
        return ms;
      };
      once('measured');
      once('dense'); // compile both first
      const measured: number[] = [];
      const dense: number[] = [];
      for (let i = 0; i < repeats; i++) {
        measured.push(once('measured'));
        dense.push(once('dense'));
      }
      return { case: name, measuredMs: median(measured), denseMs: median(dense) };
    });
  } finally {
    gl.destroy();
  }
}
