import { join } from 'node:path';
import { createBaker, type Baker } from '../../engines/bake/createBaker';
import { probeMaps, probeScene } from '../../engines/bake/probeMaps';
import { SURFACE_FRAMES } from '../../engines/bake/surfaceLayout';
import { SURFACE_NAMES, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import { createHeadlessGL } from '../node/createHeadlessGL';
import { loadLightingSceneFile, type LoadedLightingScene } from '../node/loadLightingSceneFile';
import { sampleReference } from '../../reference/sampleReference';
import { solveBoxReference } from '../../reference/solveBoxReference';
import {
  BENCH_SCENES,
  DEFAULT_QUALITY,
  METHOD_SETTINGS,
  QUALITY_LADDER,
  QUICK_LADDER,
  QUICK_SCENES,
  SCALING_LUMINAIRES,
  SCALING_QUALITY,
  SCALING_TEXELS,
  STIFF_EXTRA_OLD,
  STIFF_LADDER,
  STIFF_SCENES,
  type BenchMethod,
  type BenchQuality,
  type BenchScene,
} from './benchScenes';
import { relativeErrors } from './errorStats';
import { runFurnishedBench, type FurnishedBenchScenePart } from './furnishedBench';
import { runShapedRoomBench, type ShapedBenchScenePart } from './shapedRoomBench';
import { machineInfo, type MachineInfo } from './machineInfo';
import { runDaylightBench, type DaylightBenchScenePart } from './daylightBench';

export interface BenchRow {
  /** Scene name; rows of the old method carry " (Monte Carlo only)" so each method is its own series. */
  scene: string;
  method: BenchMethod;
  quality: BenchQuality;
  texels: number;
  /** Wall-clock time of baker.bake (all passes and the read-back), ms; compile part separately. */
  bakeMs: number;
  compileMs: number;
  /** Relative errors of total, direct and indirect illuminance at the comparison points. */
  total: { rms: number; max: number };
  direct: { rms: number; max: number };
  indirect: { rms: number; max: number };
  /** Mean total illuminance over the points: bake and reference, lux. */
  meanBake: number;
  meanReference: number;
}

export interface BenchSceneInfo {
  scene: BenchScene;
  luminaires: number;
  points: number;
  referencePatches: number;
  referenceSweeps: number;
  referenceMs: number;
  /** Total illuminance of the reference at a 2× coarser patch size against the one used, at the comparison points (convergence of the reference). */
  referenceChange: { patch: number; rms: number; max: number } | null;
}

export interface ScalingRow {
  study: 'luminaires' | 'texels';
  luminaires: number;
  pointSources: number;
  texelSize: number;
  texels: number;
  bakeMs: number;
  compileMs: number;
}

export interface BenchResult {
  quick: boolean;
  machine: MachineInfo;
  scenes: BenchSceneInfo[];
  rows: BenchRow[];
  scaling: ScalingRow[];
  scalingScene: string;
  scalingQuality: Omit<BenchQuality, 'texelSize'>;
  /** Furnished scenes (issue #10) against the furnished reference; full runs only. */
  furnished?: FurnishedBenchScenePart[];
  /** Rooms of any shape (issue 29) against the room reference; full runs only. */
  shaped?: ShapedBenchScenePart[];
  /** Daylit rooms (issue 30) against the daylight reference; full runs only. */
  daylight?: DaylightBenchScenePart[];
  totalMs: number;
}

export interface BenchOptions {
  quick: boolean;
  /** Repository root (scene files are found relative to it). */
  root: string;
  log: (line: string) => void;
}

/** Comparison points: a regular grid of cell centres on every surface, about `spacing` apart. */
export function samplePoints(room: { width: number; height: number; depth: number }, spacing: number): { surface: SurfaceName; point: Vec3 }[] {
  const ext = [room.width, room.height, room.depth];
  const out: { surface: SurfaceName; point: Vec3 }[] = [];
  for (const surface of SURFACE_NAMES) {
    const [u, v, n, far] = SURFACE_FRAMES[surface];
    const nu = Math.max(2, Math.round(ext[u] / spacing));
    const nv = Math.max(2, Math.round(ext[v] / spacing));
    for (let j = 0; j < nv; j++) {
      for (let i = 0; i < nu; i++) {
        const p: Vec3 = [0, 0, 0];
        p[n] = far ? ext[n] : 0;
        p[u] = ((i + 0.5) / nu) * ext[u];
        p[v] = ((j + 0.5) / nv) * ext[v];
        out.push({ surface, point: p });
      }
    }
  }
  return out;
}

/** The reference's photometry map: the scene's own `photometry` strings → the parsed files the loader already read. */
export function photometryMap(loaded: LoadedLightingScene): Map<string, Photometry> {
  const map = new Map<string, Photometry>();
  loaded.scene.luminaires.forEach((l, i) => map.set(l.photometry, loaded.bakeScene.luminaires[i].photometry));
  return map;
}

/**
 * One bake, timed after an untimed warm-up bake with the same texel size and
 * luminaires: the generated programs depend on both, and ANGLE finishes
 * compiling lazily at first draw, which would otherwise land in the timing.
 */
export function timedBake(baker: Baker, loaded: LoadedLightingScene, quality: BenchQuality, luminaires = loaded.bakeScene.luminaires, method: BenchMethod = 'bright-patches') {
  const extra = METHOD_SETTINGS[method];
  baker.bake({ ...loaded.bakeScene, luminaires }, { ...quality, ...extra, samples: Math.min(quality.samples, 16), bounces: Math.min(quality.bounces, 1) });
  const started = performance.now();
  const { maps, report } = baker.bake({ ...loaded.bakeScene, luminaires }, { ...quality, ...extra });
  return { maps, report, ms: performance.now() - started };
}

type ReferenceSamples = ReturnType<typeof sampleReference>[];

/** The converged CPU reference of a bench scene at its comparison points (and, where asked, its change at twice the patch size). */
function benchReference(scene: BenchScene, loaded: LoadedLightingScene, options: BenchOptions): { info: BenchSceneInfo; points: ReturnType<typeof samplePoints>; ref: ReferenceSamples } {
  const t0 = performance.now();
  const reference = solveBoxReference(loaded.scene, photometryMap(loaded), { patchSize: scene.referencePatch });
  const points = samplePoints(loaded.scene.room, scene.sampleSpacing);
  const ref = points.map(({ surface, point }) => sampleReference(reference, point, surface));
  const referenceMs = performance.now() - t0;
  let referenceChange: BenchSceneInfo['referenceChange'] = null;
  if (scene.referenceCheckPatch) {
    const coarse = solveBoxReference(loaded.scene, photometryMap(loaded), { patchSize: scene.referenceCheckPatch });
    const e = relativeErrors(
      points.map(({ surface, point }) => sampleReference(coarse, point, surface).total),
      ref.map((r) => r.total),
    );
    referenceChange = { patch: scene.referenceCheckPatch, rms: e.rms, max: e.max };
    options.log(`${scene.name}: reference at ${scene.referenceCheckPatch} m vs ${scene.referencePatch} m patches: RMS ${(100 * e.rms).toFixed(2)} %, max ${(100 * e.max).toFixed(1)} %`);
  }
  options.log(`${scene.name}: reference ${reference.patches} patches, ${reference.sweeps} sweeps, ${Math.round(referenceMs)} ms; ${points.length} points`);
  const info = { scene, luminaires: loaded.scene.luminaires.length, points: points.length, referencePatches: reference.patches, referenceSweeps: reference.sweeps, referenceMs, referenceChange };
  return { info, points, ref };
}

/**
 * Today's method over the ladder; the old one (issue #8) beside it: over the stiff ladder and with
 * 4× samples on stiff scenes, at the default rung on smooth ones.
 */
function benchRuns(scene: BenchScene, quick: boolean, ladder: readonly BenchQuality[]): [BenchMethod, BenchQuality][] {
  if (quick)
    return ladder.flatMap((q): [BenchMethod, BenchQuality][] => [
      ['bright-patches', q],
      ['monte-carlo', q],
    ]);
  if (scene.stiff) return [...STIFF_LADDER.map((q): [BenchMethod, BenchQuality] => ['bright-patches', q]), ...[...STIFF_LADDER, ...STIFF_EXTRA_OLD].map((q): [BenchMethod, BenchQuality] => ['monte-carlo', q])];
  return [...ladder.map((q): [BenchMethod, BenchQuality] => ['bright-patches', q]), ['monte-carlo', DEFAULT_QUALITY]];
}

/** One timed bake of a scene by one method at one rung, its errors at the comparison points. */
function benchRow(baker: Baker, scene: BenchScene, loaded: LoadedLightingScene, sampled: { points: ReturnType<typeof samplePoints>; ref: ReferenceSamples }, method: BenchMethod, quality: BenchQuality): BenchRow {
  const { points, ref } = sampled;
  const { maps, report, ms } = timedBake(baker, loaded, quality, loaded.bakeScene.luminaires, method);
  // The old probe read direct light from the maps; today's evaluates it at the point.
  const probes =
    method === 'monte-carlo'
      ? points.map(({ point }) => probeMaps(maps, loaded.scene.room, point))
      : probeScene(
          loaded.bakeScene,
          maps,
          { ...quality },
          points.map((p) => p.point),
        );
  const peak = Math.max(...ref.map((r) => r.total));
  const errors = (kind: 'total' | 'direct' | 'indirect', floor: number) => {
    const e = relativeErrors(
      probes.map((p) => p[kind]),
      ref.map((r) => r[kind]),
      floor,
    );
    return { rms: e.rms, max: e.max };
  };
  return {
    scene: method === 'monte-carlo' ? `${scene.name} (Monte Carlo only)` : scene.name,
    method,
    quality,
    texels: report.totalTexels,
    bakeMs: ms,
    compileMs: report.timings_ms.compile,
    total: errors('total', 0),
    // Direct light is zero in places (behind a lamp); judge it where it matters.
    direct: errors('direct', 0.01 * peak),
    indirect: errors('indirect', 0),
    meanBake: probes.reduce((s, p) => s + p.total, 0) / probes.length,
    meanReference: ref.reduce((s, r) => s + r.total, 0) / ref.length,
  };
}

/** How bake time grows with the luminaire count and the texel count, on the living room (quick: the cube). */
function scalingStudy(baker: Baker, options: BenchOptions): { rows: ScalingRow[]; scene: BenchScene } {
  const scalingScene = options.quick ? QUICK_SCENES[0] : BENCH_SCENES[1];
  const loaded = loadLightingSceneFile(join(options.root, scalingScene.file));
  const all = loaded.bakeScene.luminaires;
  const scaling: ScalingRow[] = [];
  const counts = options.quick ? [1] : SCALING_LUMINAIRES.filter((n) => n <= all.length);
  const texels = options.quick ? [0.25, 0.2] : SCALING_TEXELS;
  for (const n of counts) {
    const quality = { ...SCALING_QUALITY, texelSize: texels[1] };
    const { report, ms } = timedBake(baker, loaded, quality, all.slice(0, n));
    scaling.push({ study: 'luminaires', luminaires: n, pointSources: report.pointSources, texelSize: quality.texelSize, texels: report.totalTexels, bakeMs: ms, compileMs: report.timings_ms.compile });
    options.log(`scaling: ${n} luminaires (${report.pointSources} point sources): ${Math.round(ms)} ms`);
  }
  for (const texelSize of texels) {
    const { report, ms } = timedBake(baker, loaded, { ...SCALING_QUALITY, texelSize });
    scaling.push({ study: 'texels', luminaires: all.length, pointSources: report.pointSources, texelSize, texels: report.totalTexels, bakeMs: ms, compileMs: report.timings_ms.compile });
    options.log(`scaling: texel ${texelSize} m (${report.totalTexels} texels): ${Math.round(ms)} ms`);
  }
  return { rows: scaling, scene: scalingScene };
}

/**
 * `luxbox bench`: bakes the named scenes at each rung of the quality ladder and
 * measures the error against the converged CPU reference, then how bake time
 * grows with the number of luminaires and with the texel count; full runs add the
 * furnished rooms, the rooms of any shape and the daylit rooms.
 */
export function runBench(options: BenchOptions): BenchResult {
  const started = performance.now();
  const scenes = options.quick ? QUICK_SCENES : [...BENCH_SCENES, ...STIFF_SCENES];
  const ladder = options.quick ? QUICK_LADDER : QUALITY_LADDER;
  const gl = createHeadlessGL();
  try {
    const baker = createBaker(gl);
    const machine = machineInfo(gl);
    options.log(`machine: ${machine.cpuModel}, ${machine.cores} cores; GL: ${machine.glRenderer}`);
    const infos: BenchSceneInfo[] = [];
    const rows: BenchRow[] = [];
    for (const scene of scenes) {
      const loaded = loadLightingSceneFile(join(options.root, scene.file));
      const sampled = benchReference(scene, loaded, options);
      infos.push(sampled.info);
      for (const [method, quality] of benchRuns(scene, options.quick, ladder)) {
        const row = benchRow(baker, scene, loaded, sampled, method, quality);
        rows.push(row);
        options.log(
          `  ${method}, texel ${quality.texelSize} m, ${quality.samples} samples, ${quality.bounces} bounces: ${Math.round(row.bakeMs)} ms, total RMS ${(100 * row.total.rms).toFixed(2)} %, max ${(100 * row.total.max).toFixed(1)} %`,
        );
      }
    }
    const scaling = scalingStudy(baker, options);
    const furnished = options.quick ? undefined : runFurnishedBench(baker, options.root, options.log);
    const shaped = options.quick ? undefined : runShapedRoomBench(baker, options.root, options.log);
    const daylight = options.quick ? undefined : runDaylightBench(baker, options.log);
    return {
      quick: options.quick,
      machine,
      furnished,
      shaped,
      daylight,
      scenes: infos,
      rows,
      scaling: scaling.rows,
      scalingScene: scaling.scene.name,
      scalingQuality: SCALING_QUALITY,
      totalMs: performance.now() - started,
    };
  } finally {
    gl.destroy();
  }
}
