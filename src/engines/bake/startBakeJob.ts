import { SURFACE_NAMES, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import { blurPass } from '../../../shaders/blurPass.glsl';
import { chartBlurPass } from '../../../shaders/chartBlurPass.glsl';
import { chartDilatePass } from '../../../shaders/chartDilatePass.glsl';
import { InputError } from '../../core/inputError';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import type { BakedMaps } from './bakedMaps';
import type { BakeJob, BakeProgress, DirectMaps } from './bakeJob';
import { bakeReport } from './bakeReport';
import { toRgb, type BakeScene } from './bakeScene';
import type { BakeSettings } from './bakeSettings';
import { brightPatchOptions } from './brightPatchOptions';
import { createBakeTimer } from './createBakeTimer';
import { createBounceIteration, type BounceIteration } from './createBounceIteration';
import { createPassCompiler } from './createPassCompiler';
import { finalizeMaps, type FinalObjects, type FinalPasses } from './finalizeMaps';
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
import { acquireBounceTargets, acquireSurfaceTargets, releaseSurfaceTargets, type BounceTargets } from './surfaceTargets';
import { objectReport, type ObjectReportEntry } from './objects/objectPassReport';
import { uploadObjectPassInputs, type ObjectPassInputs } from './objects/objectPassInputs';
import { prepareObjectsCached } from './objects/prepareObjectsCached';
import { OBJECT_ROOM_TOLERANCE } from '../../core/model/lightingScene/parseLightingScene';
import type { PreparedObjects } from './objects/preparedObjects';
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
  objectDirectOverride: Float32Array | null = null,
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
  // Objects (docs/baker.md, "Objects: passes"): none, or an empty list, is exactly the empty room.
  // Given direct maps (startFromDirect) with objects come with the atlas's direct map.
  const prepared = scene.objects && scene.objects.length > 0 ? prepareSceneObjects(scene, settings) : null;
  if (directOverride && prepared) {
    const expected = prepared.atlas.width * prepared.atlas.height * 3;
    if (!objectDirectOverride) throw new Error('startFromDirect: the scene has objects but no direct map of their atlas was given');
    if (objectDirectOverride.length !== expected) {
      throw new Error(`startFromDirect: the objects' direct map has ${objectDirectOverride.length / 3} texels, their atlas ${prepared.atlas.width}×${prepared.atlas.height}`);
    }
  }
  const dataTexture = table.layouts.length > 0 ? createDataTexture(gl, table.data, DATA_TEXTURE_WIDTH, table.rows) : null;
  const objectInputs: ObjectPassInputs | null = prepared ? uploadObjectPassInputs(gl, prepared) : null;

  pool.nextJob();
  const surfaces = layouts.map((layout) => acquireSurfaceTargets(pool, layout));
  const atlas = prepared?.atlas ?? null;
  const atlasTargets: BounceTargets | null = atlas ? acquireBounceTargets(pool, atlas.width, atlas.height) : null;
  const atlasShown = atlas ? { direct: pool.acquire(atlas.width, atlas.height), indirect: pool.acquire(atlas.width, atlas.height), total: pool.acquire(atlas.width, atlas.height) } : null;
  // Every receiver the bounces run over: the six surfaces, then the atlas.
  const receivers: BounceTargets[] = atlasTargets ? [...surfaces, atlasTargets] : surfaces;
  const planObjects =
    prepared && objectInputs
      ? { bvhWidth: prepared.bvh.width, atlasWidth: prepared.atlas.width, atlasHeight: prepared.atlas.height, maxReflectance: objectInputs.maxReflectance }
      : null;
  // Given direct maps: whether any light enters is decided from every given map, the atlas's included.
  const given = directOverride && prepared && objectDirectOverride ? { ...directOverride, objects: objectDirectOverride } : directOverride;
  const plan = planBakePasses(layouts, lamps, roomSize, reflectance, settings, given, planObjects);
  startPrograms(gl, plan.sources);
  const bvhSamplers = objectInputs ? { uBvhNodes: objectInputs.bvhNodes, uBvhTriangles: objectInputs.bvhTriangles } : {};

  const directSkipped: SurfaceName[] = [];
  timed('direct', () => {
    surfaces.forEach((st, s) => {
      const pass = plan.direct[s];
      // With objects the pass also takes the BVH (generateShadowedDirectShader).
      const values = { uProfiles: dataTexture!, ...bvhSamplers, ...pass?.lampValues };
      if (directOverride) uploadRgb(gl, st.direct, directOverride[st.layout.name]);
      else if (pass) runPass(gl, compile(pass, 'direct', st.layout.name), st.direct, values);
      else {
        directSkipped.push(st.layout.name);
        clearTarget(gl, st.direct);
      }
    });
    if (atlasTargets && objectInputs) {
      if (directOverride && objectDirectOverride) uploadRgb(gl, atlasTargets.direct, objectDirectOverride);
      else if (plan.objectDirect) {
        runPass(gl, compile(plan.objectDirect, 'direct objects'), atlasTargets.direct, {
          uProfiles: dataTexture!,
          uBvhNodes: objectInputs.bvhNodes,
          uBvhTriangles: objectInputs.bvhTriangles,
          uPoints: objectInputs.points,
          uNormals: objectInputs.normals,
          ...plan.objectDirect.lampValues,
        });
      } else clearTarget(gl, atlasTargets.direct);
    }
  });

  // Flux statistics per bounce (for the tail and the report) stay on the GPU: record 0 is the direct light, record k bounce k.
  const fluxObjects =
    prepared && objectInputs
      ? {
          width: prepared.atlas.width,
          height: prepared.atlas.height,
          texelSize: prepared.atlas.texelSize,
          points: objectInputs.points,
          reflectance: objectInputs.reflectance,
          maxReflectance: objectInputs.maxReflectance,
        }
      : null;
  const statistics = createFluxStatistics(gl, pool, layouts, reflectance, settings.bounces + 1, countRead, fluxObjects);
  // Record 0 (the direct light) feeds the tail of bounce 1; a bake without indirect light (a
  // relighting basis: bounces 0) needs it only for its report, so it is recorded then, lazily.
  let directRecorded = false;
  const recordDirect = () => {
    if (directRecorded) return;
    directRecorded = true;
    timed('blend', () => statistics.record(0, receivers.map((st) => st.direct), 1));
  };
  if (plan.indirectEnabled) recordDirect();
  const passes: FinalPasses = {
    combineTail: plan.indirectEnabled ? compile(combineTailPass, 'combine') : null,
    combine: compile(combinePass, 'combine'),
    blur: plan.blur ? compile(blurPass, 'blur') : null,
  };
  const gather = plan.gather.map((pass, s) => compile(pass, 'gather', layouts[s].name));
  if (plan.objectGather) gather.push(compile(plan.objectGather, 'gather objects'));
  const objectSamplers = objectInputs
    ? { uObjectRho: objectInputs.reflectance, uBvhNodes: objectInputs.bvhNodes, uBvhTriangles: objectInputs.bvhTriangles, uPoints: objectInputs.points, uNormals: objectInputs.normals }
    : null;
  const brightObjects =
    prepared && objectInputs
      ? {
          bvhWidth: prepared.bvh.width,
          atlasWidth: prepared.atlas.width,
          atlasHeight: prepared.atlas.height,
          uBvhNodes: objectInputs.bvhNodes,
          uBvhTriangles: objectInputs.bvhTriangles,
          uPoints: objectInputs.points,
          uNormals: objectInputs.normals,
        }
      : null;
  // Bounce 1 from the brightest tiles of the direct maps, exactly (runBrightPatchPass.ts).
  const brightPass = plan.indirectEnabled
    ? timed('direct', () =>
        runBrightPatchPass(gl, layouts, reflectance, surfaces.map((st) => st.direct), brightPatchOptions(settings), compile, countRead, pool, brightObjects),
      )
    : null;
  const bounces: BounceIteration | null = plan.indirectEnabled
    ? createBounceIteration(gl, receivers, { gather, combine: passes.combine }, statistics, brightPass, settings, timer, objectSamplers)
    : null;
  const finalObjects: FinalObjects | null =
    atlasTargets && atlasShown && objectInputs
      ? {
          targets: atlasTargets,
          chartBlur: plan.blur ? compile(chartBlurPass, 'blur objects') : null,
          dilate: compile(chartDilatePass, 'dilate objects'),
          charts: objectInputs.normals,
          coverage: objectInputs.points,
          shown: atlasShown,
        }
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
    finalizeMaps(gl, receivers, passes, bounces, statistics, settings, timer, finalObjects);
    finalized = true;
  };

  let disposed = false;
  let records: FluxRecord[] | null = null;
  let objectEntries: ObjectReportEntry[] | null = null;
  const read = (t: FloatTarget) => {
    countRead(t.width * t.height * 16);
    return readRgb(gl, t);
  };
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
      const textures = Object.fromEntries(
        surfaces.map((st) => [st.layout.name, { direct: st.direct.texture, indirect: st.indirect.texture, total: st.total.texture }]),
      ) as ReturnType<BakeJob['textures']>;
      if (atlasShown) textures.objects = { direct: atlasShown.direct.texture, indirect: atlasShown.indirect.texture, total: atlasShown.total.texture };
      return textures;
    },
    readDirect() {
      if (!finalized) finalize();
      return timed('readback', () => {
        const out: DirectMaps = {
          surfaces: Object.fromEntries(surfaces.map((st) => [st.layout.name, read(st.direct)])) as DirectMaps['surfaces'],
        };
        if (prepared && atlasShown && atlasTargets) out.objects = { atlas: prepared.atlas, emitted: read(atlasTargets.direct), shown: read(atlasShown.direct) };
        return out;
      });
    },
    readMaps() {
      if (!finalized) finalize();
      return timed('readback', () => {
        const maps = Object.fromEntries(
          surfaces.map((st) => [st.layout.name, { layout: st.layout, direct: read(st.direct), indirect: read(st.indirect), total: read(st.total) }]),
        ) as unknown as BakedMaps;
        if (prepared && atlasShown) {
          maps.objects = { atlas: prepared.atlas, direct: read(atlasShown.direct), indirect: read(atlasShown.indirect), total: read(atlasShown.total) };
          objectEntries = objectReport(prepared, maps.objects.total);
        }
        return maps;
      });
    },
    report() {
      const bouncesComputed = bounces?.bounce ?? 0;
      recordDirect();
      // One read-back of the stats row, only now (never between bounces).
      if (!records || records.length !== bouncesComputed + 1) records = timed('readback', () => statistics.read(bouncesComputed + 1));
      if (prepared && atlasShown && !objectEntries) {
        if (!finalized) finalize();
        objectEntries = timed('readback', () => objectReport(prepared, read(atlasShown.total)));
      }
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
        ...(objectEntries ? { objects: objectEntries } : {}),
      });
    },
    dispose() {
      if (disposed) return;
      disposed = true;
      for (const st of receivers) releaseSurfaceTargets(pool, st);
      if (atlasShown) for (const t of Object.values(atlasShown)) pool.release(t);
      objectInputs?.dispose();
      statistics.dispose();
      if (dataTexture) gl.deleteTexture(dataTexture);
      brightPass?.dispose();
    },
  };
}

/**
 * The scene's objects prepared for the GPU (objects/prepareObjects.ts): the atlas at the bake's
 * texel size (at most maxTextureSize per edge), after checking that every object lies inside the
 * room (OBJECT_ROOM_TOLERANCE, the scene file's 1 cm: a mesh exported a few mm below its floor
 * still bakes, with finite values): the passes trace rays only inside the box.
 */
function prepareSceneObjects(scene: BakeScene, settings: BakeSettings): PreparedObjects {
  const prepared = prepareObjectsCached(scene.objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
  const size = [scene.room.width, scene.room.height, scene.room.depth];
  prepared.objects.forEach((o, k) => {
    const inside = [0, 1, 2].every((a) => o.bounds.min[a] >= -OBJECT_ROOM_TOLERANCE && o.bounds.max[a] <= size[a] + OBJECT_ROOM_TOLERANCE);
    if (!inside) {
      const fmt = (v: readonly number[]) => `(${v.map((x) => x.toFixed(3)).join(', ')})`;
      throw new InputError(`object ${k + 1} ("${o.id}") reaches outside the room: its bounds ${fmt(o.bounds.min)}–${fmt(o.bounds.max)} m, the room 0–${fmt(size)} m`);
    }
  });
  return prepared;
}
