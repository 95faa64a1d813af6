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

/**
 * The last step of startBakeJob: the job a caller drives. `step` runs the bounces, `finalize`
 * builds indirect and total maps from the current state, the read-backs finalize first when
 * needed, and `report` reads the flux statistics once (never between bounces).
 */
export function createBakeJobHandle(b: StartedBake): BakeJob {
  const { gl, settings, timer, targets, statistics, bounces } = b;
  const { atlasShown } = targets;
  const prepared = b.inputs.objects?.prepared ?? null;
  let finalized = false;
  let disposed = false;
  let records: FluxRecord[] | null = null;
  let objectEntries: ObjectReportEntry[] | null = null;
  const progress = (): BakeProgress => ({
    bounce: bounces?.bounce ?? 0,
    bounces: bounces ? settings.bounces : 0,
    samplesDone: bounces?.samplesDone ?? 0,
    samplesPerBounce: settings.samples,
    done: !bounces || bounces.bounce >= settings.bounces,
  });
  const step = (maxSamples = settings.samplesPerDraw): BakeProgress => {
    if (bounces?.step(maxSamples)) finalized = false;
    return progress();
  };
  const finalize = () => {
    finalizeMaps(gl, targets.receivers, b.passes, bounces, statistics, settings, timer, b.finalObjects);
    finalized = true;
  };
  const ensureFinalized = () => {
    if (!finalized) finalize();
  };
  const read = (t: FloatTarget) => {
    b.readbacks.counted(t.width * t.height * 16);
    return readRgb(gl, t);
  };
  return {
    layouts: b.inputs.layouts,
    get progress() {
      return progress();
    },
    step,
    run() {
      while (!progress().done) step(settings.samples);
      finalize();
    },
    finalize,
    textures: () => jobTextures(targets),
    readDirect() {
      ensureFinalized();
      return timer.timed('readback', () => readDirectMaps(targets, prepared, read));
    },
    readMaps() {
      ensureFinalized();
      return timer.timed('readback', () => {
        const maps = readAllMaps(targets, prepared, read);
        if (prepared && maps.objects) objectEntries = objectReport(prepared, maps.objects.total);
        return maps;
      });
    },
    report() {
      const bouncesComputed = bounces?.bounce ?? 0;
      b.recordDirect();
      // One read-back of the stats row, only now (never between bounces).
      if (!records || records.length !== bouncesComputed + 1) records = timer.timed('readback', () => statistics.read(bouncesComputed + 1));
      if (prepared && atlasShown && !objectEntries) {
        ensureFinalized();
        objectEntries = timer.timed('readback', () => objectReport(prepared, read(atlasShown.total)));
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
        records,
        linearFiltering: b.linear,
        shaders: b.shaders,
        timings: timer.timings,
        readbacks: { count: b.readbacks.count, bytes: b.readbacks.bytes },
        ...(objectEntries ? { objects: objectEntries } : {}),
      });
    },
    dispose() {
      if (disposed) return;
      disposed = true;
      targets.release();
      b.inputs.dispose();
      statistics.dispose();
      b.brightPass?.dispose();
    },
  };
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
