import { SURFACE_NAMES, type SurfaceName, type Vec3 } from '../../core/model/lightingScene';
import { blurPass } from '../../../shaders/blurPass.glsl';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import type { BakedMaps } from './bakedMaps';
import type { BakeJob, BakeProgress } from './bakeJob';
import { bakeReport } from './bakeReport';
import { toRgb, type BakeScene } from './bakeScene';
import type { BakeSettings } from './bakeSettings';
import { brightPatchOptions } from './brightPatchOptions';
import { createBakeTimer } from './createBakeTimer';
import { createBounceIteration, type BounceIteration } from './createBounceIteration';
import { createPassCompiler } from './createPassCompiler';
import { finalizeMaps, type FinalPasses } from './finalizeMaps';
import { createFluxStatistics, type FluxRecord } from './fluxStatistics';
import { startPrograms } from './glResources';
import { clearTarget, readRgb, uploadRgb, type FloatTarget } from './floatTarget';
import { createDataTexture } from './createDataTexture';
import { planBakePasses } from './planBakePasses';
import { prepareLamps } from './prepareLamps';
import { DATA_TEXTURE_WIDTH } from './profileTable';
import { runBrightPatchPass } from './runBrightPatchPass';
import { runPass } from './runPass';
import { surfaceLayouts } from './surfaceLayout';
import { acquireSurfaceTargets, releaseSurfaceTargets } from './surfaceTargets';
import type { TargetPool } from './targetPool';

/**
 * One bake (docs/baker.md, "Passes"): plan and start compiling its passes,
 * run the direct pass now (or upload given direct maps), record the direct
 * flux, run the bright-patch pass, and return the job whose `step` runs the
 * bounces and whose `finalize` builds the indirect and total maps.
 */
export function startBakeJob(
  gl: WebGL2RenderingContext,
  linear: boolean,
  pool: TargetPool,
  scene: BakeScene,
  settings: BakeSettings,
  directOverride: Record<SurfaceName, Float32Array> | null,
): BakeJob {
  const t0 = performance.now();
  const timer = createBakeTimer(gl, settings.syncTimings);
  const { timings, timed } = timer;
  const { compile, shaders } = createPassCompiler(gl, timings);
  const readbacks = { count: 0, bytes: 0 };
  const countRead = (bytes: number) => {
    readbacks.count++;
    readbacks.bytes += bytes;
  };
  const { room } = scene;
  const roomSize: Vec3 = [room.width, room.height, room.depth];
  const reflectance = SURFACE_NAMES.map((n) => toRgb(room.reflectance[n]));
  const layouts = surfaceLayouts(room, settings.texelSize, settings.maxTextureSize);
  const { table, lamps, pointSources } = prepareLamps(scene, settings);
  const dataTexture = table.layouts.length > 0 ? createDataTexture(gl, table.data, DATA_TEXTURE_WIDTH, table.rows) : null;

  pool.nextJob();
  const surfaces = layouts.map((layout) => acquireSurfaceTargets(pool, layout));
  const plan = planBakePasses(layouts, lamps, roomSize, reflectance, settings, directOverride);
  startPrograms(gl, plan.sources);

  const directSkipped: SurfaceName[] = [];
  timed('direct', () => {
    surfaces.forEach((st, s) => {
      const pass = plan.direct[s];
      if (directOverride) uploadRgb(gl, st.direct, directOverride[st.layout.name]);
      else if (pass) runPass(gl, compile(pass, 'direct', st.layout.name), st.direct, { uProfiles: dataTexture! });
      else {
        directSkipped.push(st.layout.name);
        clearTarget(gl, st.direct);
      }
    });
  });

  // Flux statistics per bounce (for the tail and the report) stay on the GPU: record 0 is the direct light, record k bounce k.
  const statistics = createFluxStatistics(gl, pool, layouts, reflectance, settings.bounces + 1, countRead);
  timed('blend', () => statistics.record(0, surfaces.map((st) => st.direct), 1));
  const passes: FinalPasses = {
    combineTail: plan.indirectEnabled ? compile(combineTailPass, 'combine') : null,
    combine: compile(combinePass, 'combine'),
    blur: plan.blur ? compile(blurPass, 'blur') : null,
  };
  const gather = plan.gather.map((pass, s) => compile(pass, 'gather', layouts[s].name));
  // Bounce 1 from the brightest tiles of the direct maps, exactly (runBrightPatchPass.ts).
  const brightPass = plan.indirectEnabled
    ? timed('direct', () => runBrightPatchPass(gl, layouts, reflectance, surfaces.map((st) => st.direct), brightPatchOptions(settings), compile, countRead, pool))
    : null;
  const bounces: BounceIteration | null = plan.indirectEnabled
    ? createBounceIteration(gl, surfaces, { gather, combine: passes.combine }, statistics, brightPass, settings, timer)
    : null;

  let finalized = false;
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
    finalizeMaps(gl, surfaces, passes, bounces, statistics, settings, timer);
    finalized = true;
  };

  let disposed = false;
  let records: FluxRecord[] | null = null;
  return {
    layouts,
    get progress() {
      return progress();
    },
    step,
    run() {
      while (!progress().done) step(settings.samples);
      finalize();
    },
    finalize,
    textures() {
      return Object.fromEntries(
        surfaces.map((st) => [st.layout.name, { direct: st.direct.texture, indirect: st.indirect.texture, total: st.total.texture }]),
      ) as ReturnType<BakeJob['textures']>;
    },
    readMaps() {
      if (!finalized) finalize();
      const read = (t: FloatTarget) => {
        countRead(t.width * t.height * 16);
        return readRgb(gl, t);
      };
      return timed('readback', () =>
        Object.fromEntries(
          surfaces.map((st) => [st.layout.name, { layout: st.layout, direct: read(st.direct), indirect: read(st.indirect), total: read(st.total) }]),
        ) as unknown as BakedMaps,
      );
    },
    report() {
      const bouncesComputed = bounces?.bounce ?? 0;
      // One read-back of the stats row, only now (never between bounces).
      if (!records || records.length !== bouncesComputed + 1) records = timed('readback', () => statistics.read(bouncesComputed + 1));
      timings.total = performance.now() - t0;
      return bakeReport({
        settings,
        layouts,
        luminaires: scene.luminaires.length,
        pointSources,
        directSkipped,
        indirectEnabled: plan.indirectEnabled,
        brightSelection: brightPass?.selection ?? null,
        bouncesComputed,
        records,
        linearFiltering: linear,
        shaders,
        timings,
        readbacks,
      });
    },
    dispose() {
      if (disposed) return;
      disposed = true;
      for (const st of surfaces) releaseSurfaceTargets(pool, st);
      statistics.dispose();
      if (dataTexture) gl.deleteTexture(dataTexture);
      brightPass?.dispose();
    },
  };
}
