import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakedMaps } from './bakedMaps';
import type { BakeJob, BakeProgress, DirectMaps } from './bakeJob';
import type { BakeJobTargets } from './bakeJobTargets';
import { bakeReport } from './bakeReport';
import type { BakeSettings } from './bakeSettings';
import type { BakeTimer } from './createBakeTimer';
import type { BounceIteration } from './createBounceIteration';
import type { BakeReport } from './bakeJob';
import { finalizeMaps, type FinalObjects, type FinalPasses } from './finalizeMaps';
import { readRgb, type FloatTarget } from './floatTarget';
import type { FluxRecord, FluxStatistics } from './fluxStatistics';
import { objectReport, type ObjectReportEntry } from './objects/objectPassReport';
import type { PreparedObjects } from './objects/preparedObjects';
import type { BakeInputs } from './prepareBakeInputs';
import type { BrightPatchPass } from './runBrightPatchPass';

/** What a started bake hands to its job: the state after the direct pass, and what the report needs. */
export interface StartedBake {
  gl: WebGL2RenderingContext;
  settings: BakeSettings;
  luminaires: number;
  linear: boolean;
  startedAt: number;
  timer: BakeTimer;
  shaders: BakeReport['shaders'];
  readbacks: { count: number; bytes: number; counted(bytes: number): void };
  inputs: BakeInputs;
  targets: BakeJobTargets;
  directSkipped: SurfaceName[];
  indirectEnabled: boolean;
  statistics: FluxStatistics;
  /** Records the direct light's flux (record 0) once: at start when it feeds the tail, else when the report asks. */
  recordDirect(): void;
  passes: FinalPasses;
  finalObjects: FinalObjects | null;
  brightPass: BrightPatchPass | null;
  bounces: BounceIteration | null;
}

/** What the job's methods share: the started bake, and the job's own state (finalized, disposed, the report's cached read-backs). */
interface JobState {
  b: StartedBake;
  prepared: PreparedObjects | null;
  finalized: boolean;
  disposed: boolean;
  records: FluxRecord[] | null;
  objectEntries: ObjectReportEntry[] | null;
}

/**
 * The last step of startBakeJob: the job a caller drives. `step` runs the bounces, `finalize`
 * builds indirect and total maps from the current state, the read-backs finalize first when
 * needed, and `report` reads the flux statistics once (never between bounces).
 */
export function createBakeJobHandle(b: StartedBake): BakeJob {
  const { settings, timer, targets } = b;
  const job: JobState = { b, prepared: b.inputs.objects?.prepared ?? null, finalized: false, disposed: false, records: null, objectEntries: null };
  const read = (t: FloatTarget) => readCounted(b, t);
  return {
    layouts: b.inputs.layouts,
    get progress() {
      return progress(b);
    },
    step: (maxSamples = settings.samplesPerDraw) => step(job, maxSamples),
    run() {
      while (!progress(b).done) step(job, settings.samples);
      finalize(job);
    },
    finalize: () => finalize(job),
    textures: () => jobTextures(targets),
    readDirect() {
      ensureFinalized(job);
      return timer.timed('readback', () => readDirectMaps(targets, job.prepared, read));
    },
    readMaps() {
      ensureFinalized(job);
      return timer.timed('readback', () => {
        const maps = readAllMaps(targets, job.prepared, read);
        if (job.prepared && maps.objects) job.objectEntries = objectReport(job.prepared, maps.objects.total);
        return maps;
      });
    },
    report: () => jobReport(job),
    dispose: () => disposeJob(job),
  };
}

function progress({ bounces, settings }: StartedBake): BakeProgress {
  return {
    bounce: bounces?.bounce ?? 0,
    bounces: bounces ? settings.bounces : 0,
    samplesDone: bounces?.samplesDone ?? 0,
    samplesPerBounce: settings.samples,
    done: !bounces || bounces.bounce >= settings.bounces,
  };
}

/** Up to `maxSamples` more samples; a step that gathered any makes the finalized maps stale. */
function step(job: JobState, maxSamples: number): BakeProgress {
  if (job.b.bounces?.step(maxSamples)) job.finalized = false;
  return progress(job.b);
}

function finalize(job: JobState): void {
  const { b } = job;
  finalizeMaps(b.gl, b.targets.receivers, b.passes, b.bounces, b.statistics, b.settings, b.timer, b.finalObjects);
  job.finalized = true;
}

function ensureFinalized(job: JobState): void {
  if (!job.finalized) finalize(job);
}

/** One read-back of a target, counted for the report. */
function readCounted(b: StartedBake, t: FloatTarget): Float32Array {
  b.readbacks.counted(t.width * t.height * 16);
  return readRgb(b.gl, t);
}

/** The report: the flux records read once per bounce count, the objects' entries read once (finalizing first). */
function jobReport(job: JobState): BakeReport {
  const { b, prepared } = job;
  const { timer, targets, statistics, settings } = b;
  const bouncesComputed = b.bounces?.bounce ?? 0;
  b.recordDirect();
  // One read-back of the stats row, only now (never between bounces).
  if (!job.records || job.records.length !== bouncesComputed + 1) job.records = timer.timed('readback', () => statistics.read(bouncesComputed + 1));
  const shown = targets.atlasShown;
  if (prepared && shown && !job.objectEntries) {
    ensureFinalized(job);
    job.objectEntries = timer.timed('readback', () => objectReport(prepared, readCounted(b, shown.total)));
  }
  timer.timings.total = performance.now() - b.startedAt;
  return bakeReport({
    settings,
    layouts: b.inputs.layouts,
    luminaires: b.luminaires,
    pointSources: b.inputs.lamps.pointSources,
    directSkipped: b.directSkipped,
    indirectEnabled: b.indirectEnabled,
    brightSelection: b.brightPass?.summary() ?? null,
    bouncesComputed,
    records: job.records,
    linearFiltering: b.linear,
    shaders: b.shaders,
    timings: timer.timings,
    readbacks: { count: b.readbacks.count, bytes: b.readbacks.bytes },
    ...(job.objectEntries ? { objects: job.objectEntries } : {}),
  });
}

function disposeJob(job: JobState): void {
  if (job.disposed) return;
  job.disposed = true;
  job.b.targets.release();
  job.b.inputs.dispose();
  job.b.statistics.dispose();
  job.b.brightPass?.dispose();
}

/** The current maps on the GPU: per surface, and the atlas as shown. */
function jobTextures(targets: BakeJobTargets): ReturnType<BakeJob['textures']> {
  const textures = Object.fromEntries(targets.surfaces.map((st) => [st.layout.name, { direct: st.direct.texture, indirect: st.indirect.texture, total: st.total.texture }])) as ReturnType<BakeJob['textures']>;
  const shown = targets.atlasShown;
  if (shown) textures.objects = { direct: shown.direct.texture, indirect: shown.indirect.texture, total: shown.total.texture };
  return textures;
}

function readDirectMaps(targets: BakeJobTargets, prepared: PreparedObjects | null, read: (t: FloatTarget) => Float32Array): DirectMaps {
  const out: DirectMaps = {
    surfaces: Object.fromEntries(targets.surfaces.map((st) => [st.layout.name, read(st.direct)])) as DirectMaps['surfaces'],
  };
  if (prepared && targets.atlasShown && targets.atlas) out.objects = { atlas: prepared.atlas, emitted: read(targets.atlas.direct), shown: read(targets.atlasShown.direct) };
  return out;
}

function readAllMaps(targets: BakeJobTargets, prepared: PreparedObjects | null, read: (t: FloatTarget) => Float32Array): BakedMaps {
  const maps = Object.fromEntries(targets.surfaces.map((st) => [st.layout.name, { layout: st.layout, direct: read(st.direct), indirect: read(st.indirect), total: read(st.total) }])) as unknown as BakedMaps;
  const shown = targets.atlasShown;
  if (prepared && shown) maps.objects = { atlas: prepared.atlas, direct: read(shown.direct), indirect: read(shown.indirect), total: read(shown.total) };
  return maps;
}
