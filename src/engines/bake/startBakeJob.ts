import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { blurPass } from '../../../shaders/blurPass.glsl';
import { chartBlurPass } from '../../../shaders/chartBlurPass.glsl';
import { chartDilatePass } from '../../../shaders/chartDilatePass.glsl';
import { combinePass } from '../../../shaders/combinePass.glsl';
import { combineTailPass } from '../../../shaders/combineTailPass.glsl';
import type { BakeJob } from './bakeJob';
import { acquireBakeJobTargets, type BakeJobTargets } from './bakeJobTargets';
import type { BakeScene } from './bakeScene';
import type { BakeSettings } from './bakeSettings';
import { softwareRenderer } from './softwareRenderer';
import { brightPatchOptions } from './brightPatchOptions';
import { createBakeJobHandle, type StartedBake } from './createBakeJobHandle';
import { createBakeTimer } from './createBakeTimer';
import { createBounceIteration } from './createBounceIteration';
import { createPassCompiler, type CompilePass } from './createPassCompiler';
import type { FinalObjects, FinalPasses } from './finalizeMaps';
import { createFluxStatistics } from './fluxStatistics';
import { startPrograms } from './glResources';
import { objectPassViews } from './objectPassViews';
import { planBakePasses, type BakePlan } from './planBakePasses';
import { prepareBakeInputs, type BakeInputs } from './prepareBakeInputs';
import { runBrightPatchPass } from './runBrightPatchPass';
import { runDirectPasses, type GivenDirect } from './runDirectPasses';
import type { TargetPool } from './targetPool';

/**
 * One bake (docs/baker.md, "Passes"), as a sequence of named steps:
 * 1. prepareBakeInputs — surface layouts, lamps (profile table), objects (atlas, BVH), uploaded;
 * 2. acquireBakeJobTargets — the render targets of the surfaces and the atlas;
 * 3. planBakePasses — which passes run, their compiles started together;
 * 4. runDirectPasses — the direct maps (or the given ones uploaded);
 * 5. createFluxStatistics — flux records on the GPU; the direct light's first when it bounces;
 * 6. runBrightPatchPass — the first bounce of the brightest tiles, exactly;
 * 7. createBounceIteration — the bounces, which the job's `step` advances;
 * 8. createBakeJobHandle — the job: step, finalize, read-backs, report, dispose.
 * `directOverride` (startFromDirect) replaces step 4's passes by the given maps.
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
  const startedAt = performance.now();
  const timer = createBakeTimer(gl, settings.syncTimings);
  const { compile, shaders } = createPassCompiler(gl, timer.timings);
  const readbacks = createReadbackCounter();
  const given: GivenDirect | null = directOverride ? { surfaces: directOverride, objects: objectDirectOverride } : null;

  const inputs = prepareBakeInputs(gl, scene, settings, directOverride, objectDirectOverride);
  const views = objectPassViews(inputs.objects);
  const targets = acquireBakeJobTargets(pool, inputs.layouts, inputs.objects?.prepared.atlas ?? null);
  const plan = planPasses(gl, inputs, settings, given, views.plan);
  const directSkipped = timer.timed('direct', () => runDirectPasses(gl, compile, plan, inputs, views, targets, given));

  // Flux statistics per bounce (for the tail and the report) stay on the GPU: record 0 is the direct light, record k bounce k.
  // A room with openings lets light out: its tail ratio is measured bounce over bounce (fluxStatistics.ts).
  const openings = (scene.room.enclosure?.shape.openings.length ?? 0) > 0;
  const statistics = createFluxStatistics(gl, pool, inputs.layouts, inputs.reflectance, settings.bounces + 1, readbacks.counted, views.flux, openings);
  // Record 0 (the direct light) feeds the tail of bounce 1; a bake without indirect light (a
  // relighting basis: bounces 0) needs it only for its report, so it is recorded then, lazily.
  const recordDirect = once(() =>
    timer.timed('blend', () =>
      statistics.record(
        0,
        targets.receivers.map((st) => st.direct),
        1,
      ),
    ),
  );
  if (plan.indirectEnabled) recordDirect();
  const passes = compileFinalPasses(compile, plan);
  const gather = compileGatherPasses(compile, plan, inputs);

  // Bounce 1 from the brightest tiles of the direct maps, exactly (runBrightPatchPass.ts).
  const brightPass = plan.indirectEnabled
    ? timer.timed('direct', () =>
        runBrightPatchPass(
          gl,
          inputs.layouts,
          inputs.reflectance,
          targets.surfaces.map((st) => st.direct),
          brightPatchOptions(settings, inputs.sinks, softwareRenderer(gl)),
          compile,
          readbacks.counted,
          pool,
          views.bright,
          targets.atlas?.direct ?? null,
        ),
      )
    : null;
  const bounces = plan.indirectEnabled ? createBounceIteration(gl, targets.receivers, { gather, combine: passes.combine }, statistics, brightPass, settings, timer, views.gather) : null;

  return createBakeJobHandle({
    gl,
    settings,
    luminaires: scene.luminaires.length,
    linear,
    startedAt,
    timer,
    shaders,
    readbacks,
    inputs,
    targets,
    directSkipped,
    indirectEnabled: plan.indirectEnabled,
    statistics,
    recordDirect,
    passes,
    finalObjects: finalObjectPasses(compile, plan, inputs, targets),
    brightPass,
    bounces,
  });
}

/** Counts the job's read-backs (count and bytes) for the report. */
function createReadbackCounter(): StartedBake['readbacks'] {
  const readbacks = {
    count: 0,
    bytes: 0,
    counted(bytes: number) {
      readbacks.count++;
      readbacks.bytes += bytes;
    },
  };
  return readbacks;
}

/** `run` the first time it is called, nothing after. */
function once(run: () => void): () => void {
  let done = false;
  return () => {
    if (done) return;
    done = true;
    run();
  };
}

/** One gather pass per room surface, and the objects' atlas last when the scene has objects. */
function compileGatherPasses(compile: CompilePass, plan: BakePlan, inputs: BakeInputs) {
  const gather = plan.gather.map((pass, s) => compile(pass, 'gather', inputs.layouts[s].name));
  if (plan.objectGather) gather.push(compile(plan.objectGather, 'gather objects'));
  return gather;
}

/** Step 3: the plan, and every program it names compiling at once. Given direct maps with objects decide with the atlas's map whether any light enters. */
function planPasses(gl: WebGL2RenderingContext, inputs: BakeInputs, settings: BakeSettings, given: GivenDirect | null, objects: ReturnType<typeof objectPassViews>['plan']): BakePlan {
  const givenMaps = given && inputs.objects && given.objects ? { ...given.surfaces, objects: given.objects } : (given?.surfaces ?? null);
  const plan = planBakePasses(inputs.layouts, inputs.lamps.lamps, inputs.roomSize, inputs.reflectance, settings, givenMaps, objects, inputs.sinks);
  startPrograms(gl, plan.sources);
  return plan;
}

/** The passes every finalize runs: the combine (with the tail when light bounces) and the blur. */
function compileFinalPasses(compile: CompilePass, plan: BakePlan): FinalPasses {
  return {
    combineTail: plan.indirectEnabled ? compile(combineTailPass, 'combine') : null,
    combine: compile(combinePass, 'combine'),
    blur: plan.blur ? compile(blurPass, 'blur') : null,
  };
}

/** The atlas in the final passes: a chart-aware blur and the dilation into the maps shown (null without objects). */
function finalObjectPasses(compile: CompilePass, plan: BakePlan, inputs: BakeInputs, targets: BakeJobTargets): FinalObjects | null {
  const objects = inputs.objects?.inputs;
  if (!targets.atlas || !targets.atlasShown || !objects) return null;
  return {
    targets: targets.atlas,
    chartBlur: plan.blur ? compile(chartBlurPass, 'blur objects') : null,
    dilate: compile(chartDilatePass, 'dilate objects'),
    charts: objects.normals,
    coverage: objects.points,
    shown: targets.atlasShown,
  };
}
