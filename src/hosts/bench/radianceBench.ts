import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createBaker, type Baker } from '../../engines/bake/createBaker';
import { probeScene } from '../../engines/bake/probeMaps';
import { SURFACE_FRAMES } from '../../engines/bake/surfaceLayout';
import { exportRadiance } from '../../engines/radiance/exportRadiance';
import { toRadiance, vecText } from '../../engines/radiance/radianceFrame';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { sampleReference } from '../../reference/sampleReference';
import { solveBoxReference } from '../../reference/solveBoxReference';
import { createHeadlessGL } from '../node/createHeadlessGL';
import { loadLightingSceneFile, type LoadedLightingScene } from '../node/loadLightingSceneFile';
import { compileOctree, findRadianceBin, rtraceLux, writeExportFiles } from '../node/radianceTools';
import { BENCH_SCENES, QUALITY_LADDER, STIFF_SCENES, type BenchQuality, type BenchScene } from './benchScenes';
import { relativeErrors } from './errorStats';
import { machineInfo, type MachineInfo } from './machineInfo';
import { photometryMap, samplePoints, timedBake } from './runBench';

/**
 * Radiance settings from quick to thorough: pure Monte Carlo (-aa 0; with ambient caching a
 * -ab 8 run on the CIE cube took over ten minutes for 384 points on 2 cores), Radiance's default
 * source thresholds (-dt 0.05 -dc 0.5: with -dt 0 every one of the living room's 137 point
 * sources is tested at every bounce, 156 s for -ab 4 -ad 64 at 90 points), and a reflection
 * limit above the bounces (Radiance's default -lr 10 cuts the series of a ρ = 0.8 room short:
 * docs/radiance.md).
 */
const rtraceOptions = (ab: number, ad: number): string[] => ['-ab', String(ab), '-ad', String(ad), '-aa', '0', '-lr', String(ab + 4), '-lw', '1e-6'];
export const RADIANCE_LADDER: readonly { label: string; options: readonly string[] }[] = [
  [4, 64],
  [8, 128],
  [16, 256],
  [16, 512],
].map(([ab, ad]) => ({ label: `-ab ${ab} -ad ${ad} -aa 0`, options: rtraceOptions(ab, ad) }));

/** The scenes of the comparison: the CIE cube, the living room and the spot aimed at a wall (stiff). */
export const RADIANCE_SCENES: readonly BenchScene[] = [BENCH_SCENES[0], BENCH_SCENES[1], STIFF_SCENES[0]];

/** After a Radiance run longer than this, the scene's more expensive rungs are skipped (and listed as skipped). */
export const RADIANCE_RUNG_BUDGET_MS = 60_000;

/** Every `POINT_STRIDE`-th comparison point of the main bench: Radiance's cost is per point. */
export const POINT_STRIDE = 16;

export interface PeerRow {
  scene: string;
  solver: 'luxbox' | 'radiance';
  settings: string;
  ms: number;
  /** Illuminance values the run produced: texels of all maps (luxbox), points traced (Radiance). */
  values: number;
  total: { rms: number; max: number };
  /** Not run: the previous rung already took longer than RADIANCE_RUNG_BUDGET_MS. */
  skipped?: boolean;
}

export interface PeerResult {
  machine: MachineInfo;
  radiance: string;
  points: Record<string, number>;
  rows: PeerRow[];
}

/** The main bench's timed bake (after its untimed warm-up), plus reading the points: luxbox's time to the same numbers Radiance gives. */
function luxboxRun(baker: Baker, loaded: LoadedLightingScene, quality: BenchQuality, points: Vec3[]) {
  const { maps, report, ms } = timedBake(baker, loaded, quality);
  const t0 = performance.now();
  const values = probeScene(loaded.bakeScene, maps, quality, points).map((p) => p.total);
  return { ms: ms + performance.now() - t0, texels: report.totalTexels, values };
}

/**
 * Radiance as a peer (issue 14): the same scenes, the same comparison points, the same exact
 * reference; luxbox over its quality ladder and Radiance (`rtrace -I` on the export) over
 * RADIANCE_LADDER, in one run on one machine. Radiance runs single-threaded, luxbox on the GL
 * the machine has.
 */
export function runRadiancePeerBench(root: string, log: (line: string) => void): PeerResult {
  const bin = findRadianceBin(root);
  if (!bin) throw new Error('Radiance not found: run scripts/setup.sh (pyradiance in .venv) or set LUXBOX_RADIANCE_BIN');
  const gl = createHeadlessGL();
  const rows: PeerRow[] = [];
  const counts: Record<string, number> = {};
  try {
    const baker = createBaker(gl);
    const machine = machineInfo(gl);
    for (const scene of RADIANCE_SCENES) {
      const loaded = loadLightingSceneFile(join(root, scene.file));
      const reference = solveBoxReference(loaded.scene, photometryMap(loaded), { patchSize: scene.referencePatch });
      const sampled = samplePoints(loaded.scene.room, scene.sampleSpacing).filter((_, i) => i % POINT_STRIDE === 0);
      const ref = sampled.map(({ surface, point }) => sampleReference(reference, point, surface).total);
      counts[scene.name] = sampled.length;
      log(`${scene.name}: ${sampled.length} points`);
      for (const quality of QUALITY_LADDER) {
        const run = luxboxRun(
          baker,
          loaded,
          quality,
          sampled.map((s) => s.point),
        );
        const e = relativeErrors(run.values, ref);
        rows.push({ scene: scene.name, solver: 'luxbox', settings: `${quality.texelSize} m, ${quality.samples} samples, ${quality.bounces} bounces`, ms: run.ms, values: run.texels, total: { rms: e.rms, max: e.max } });
        log(`  luxbox ${rows.at(-1)!.settings}: ${Math.round(run.ms)} ms, RMS ${(100 * e.rms).toFixed(2)} %`);
      }
      const dir = mkdtempSync(join(tmpdir(), 'luxbox-radiance-bench-'));
      try {
        writeExportFiles(dir, exportRadiance(loaded.bakeScene, {}, scene.name));
        // Each point 1 mm into the room from its surface, the surface's inward normal as direction.
        const input = sampled
          .map(({ surface, point }) => {
            const [, , n, far] = SURFACE_FRAMES[surface];
            const normal: Vec3 = [0, 0, 0];
            normal[n] = far ? -1 : 1;
            const p: Vec3 = [point[0] + 0.001 * normal[0], point[1] + 0.001 * normal[1], point[2] + 0.001 * normal[2]];
            return `${vecText(toRadiance(p))} ${vecText(toRadiance(normal))}`;
          })
          .join('\n');
        const t0 = performance.now();
        compileOctree(bin, dir);
        const compileMs = performance.now() - t0;
        let overBudget = false;
        for (const { label, options } of RADIANCE_LADDER) {
          if (overBudget) {
            rows.push({ scene: scene.name, solver: 'radiance', settings: label, ms: NaN, values: sampled.length, total: { rms: NaN, max: NaN }, skipped: true });
            log(`  radiance ${label}: skipped (the previous rung took over ${RADIANCE_RUNG_BUDGET_MS / 1000} s)`);
            continue;
          }
          const t1 = performance.now();
          const values = rtraceLux(bin, dir, options, input + '\n');
          const ms = performance.now() - t1 + compileMs;
          const e = relativeErrors(values, ref);
          rows.push({ scene: scene.name, solver: 'radiance', settings: label, ms, values: sampled.length, total: { rms: e.rms, max: e.max } });
          log(`  radiance ${label}: ${Math.round(ms)} ms, RMS ${(100 * e.rms).toFixed(2)} %`);
          overBudget = ms > RADIANCE_RUNG_BUDGET_MS;
        }
      } finally {
        rmSync(dir, { recursive: true, force: true });
      }
    }
    return { machine, radiance: bin, points: counts, rows };
  } finally {
    gl.destroy();
  }
}

/**
 * For each Radiance run, luxbox's fastest run that is at least as accurate (total RMS), and the
 * ratio of illuminance values per second (luxbox: every texel of every map; Radiance: traced points).
 */
export function equalErrorRatios(rows: readonly PeerRow[]): { scene: string; radiance: PeerRow; luxbox: PeerRow | null; ratio: number | null }[] {
  return rows
    .filter((r) => r.solver === 'radiance' && !r.skipped)
    .map((radiance) => {
      const candidates = rows.filter((r) => r.solver === 'luxbox' && r.scene === radiance.scene && r.total.rms <= radiance.total.rms);
      const luxbox = candidates.sort((a, b) => a.ms - b.ms)[0] ?? null;
      const ratio = luxbox ? luxbox.values / luxbox.ms / (radiance.values / radiance.ms) : null;
      return { scene: radiance.scene, radiance, luxbox, ratio };
    });
}

const pct = (e: number): string => (100 * e).toFixed(2);
const time = (t: number): string => (t >= 10_000 ? `${(t / 1000).toFixed(1)} s` : `${Math.round(t)} ms`);

/** The peer comparison as markdown (its own generated section of docs/benchmarks.md). */
export function peerTables(r: PeerResult): string {
  const m = r.machine;
  const lines = [
    `Run: ${m.date}. Machine: ${m.cpuModel}, ${m.cores} logical cores; GL renderer ${m.glRenderer}. Radiance: ${r.radiance.includes('pyradiance') ? 'PyPI pyradiance' : r.radiance}, \`rtrace\` single-threaded.`,
    '',
    '| scene | solver | settings | time | values | values / s | total RMS | total max |',
    '|---|---|---|---|---|---|---|---|',
    ...r.rows.map((x) =>
      x.skipped
        ? `| ${x.scene} (${r.points[x.scene]} points) | ${x.solver} | ${x.settings} | not run: the rung before took over ${RADIANCE_RUNG_BUDGET_MS / 1000} s | | | | |`
        : `| ${x.scene} (${r.points[x.scene]} points) | ${x.solver} | ${x.settings} | ${time(x.ms)} | ${x.values} ${x.solver === 'luxbox' ? 'texels' : 'points'} | ${Math.round((1000 * x.values) / x.ms)} | ${pct(x.total.rms)} % | ${pct(x.total.max)} % |`,
    ),
    '',
    "**At equal error**: for each Radiance run, luxbox's fastest run with a total RMS error at most Radiance's, and the ratio of illuminance values per second (luxbox counts every texel of its six maps, Radiance the points it traced):",
    '',
    '| scene | Radiance | RMS | luxbox | RMS | time Radiance / luxbox | values/s luxbox / Radiance |',
    '|---|---|---|---|---|---|---|',
    ...equalErrorRatios(r.rows).map((x) =>
      x.luxbox
        ? `| ${x.scene} | ${x.radiance.settings} | ${pct(x.radiance.total.rms)} % | ${x.luxbox.settings} | ${pct(x.luxbox.total.rms)} % | ${(x.radiance.ms / x.luxbox.ms).toFixed(1)} | ${Math.round(x.ratio!)} |`
        : `| ${x.scene} | ${x.radiance.settings} | ${pct(x.radiance.total.rms)} % | none as accurate | — | — | — |`,
    ),
  ];
  return lines.join('\n');
}
