/**
 * A bake with daylight (docs/daylight.md, "The baker"): the windows are another kind of source.
 * 1. the electric light's direct maps, by the usual direct passes (a direct-only job, bounces 0);
 * 2. the direct daylight of every atlas texel (daylightAtlasDirect.ts), added to the atlas's map;
 * 3. the indirect passes on the sum, exactly as `startFromDirect` runs them (bright patches,
 *    gathers, tail, blur): light that reaches a window leaves through it into the enclosure's
 *    black sinks, so the glass is not a mirror.
 * The job's report carries the daylight's numbers (BakeReport.daylight).
 */
import type { BakeJob, BakeReport } from '../bakeJob';
import type { BakeScene } from '../bakeScene';
import type { BakeSettings } from '../bakeSettings';
import { prepareObjectsCached } from '../objects/prepareObjectsCached';
import { startBakeJob } from '../startBakeJob';
import type { TargetPool } from '../targetPool';
import type { BakeDaylight } from './bakeDaylight';
import { daylightAtlasDirect, daylightPointContext, type DaylightAtlas } from './daylightAtlasDirect';
import type { BakeWindow } from './daylightWindows';

export interface DaylightBakeInput {
  /** The enclosed scene (shapedRoom/encloseShapedRoom.ts). */
  enclosed: BakeScene;
  daylight: BakeDaylight;
  windows: readonly BakeWindow[];
  /** Whether a sight line can be blocked: a room that is not convex, or objects in it. */
  needsRays: boolean;
}

/** Σ E·coverage·texel² of a per-texel Y map over the atlas (lm). */
function atlasFlux(map: Float32Array, coverage: Float32Array, texelSize: number): number {
  let sum = 0;
  for (let k = 0; k < map.length; k++) sum += map[k] * coverage[4 * k + 3];
  return sum * texelSize * texelSize;
}

export function startDaylightBakeJob(gl: WebGL2RenderingContext, linear: boolean, pool: TargetPool, input: DaylightBakeInput, settings: BakeSettings): BakeJob & { daylightAtlas: DaylightAtlas } {
  const { enclosed } = input;
  const electric = startBakeJob(gl, linear, pool, enclosed, { ...settings, bounces: 0 }, null);
  let direct;
  try {
    electric.run();
    direct = electric.readDirect();
  } finally {
    electric.dispose();
  }
  const prepared = prepareObjectsCached(enclosed.objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
  const day = daylightAtlasDirect(prepared, daylightPointContext(prepared, input.daylight, input.windows, input.needsRays));
  const emitted = direct.objects ? direct.objects.emitted : new Float32Array(day.direct.length);
  const sum = new Float32Array(day.direct.length);
  for (let i = 0; i < sum.length; i++) sum[i] = emitted[i] + day.direct[i];
  const job = startBakeJob(gl, linear, pool, enclosed, settings, direct.surfaces, sum);
  const coverage = prepared.atlas.position;
  const facts = { windows: input.windows.length, directMs: day.milliseconds, skyFlux: atlasFlux(day.sky, coverage, prepared.atlas.texelSize), sunFlux: atlasFlux(day.sun, coverage, prepared.atlas.texelSize) };
  return {
    ...job,
    get layouts() {
      return job.layouts;
    },
    get progress() {
      return job.progress;
    },
    report: (): BakeReport => ({ ...job.report(), daylight: facts }),
    daylightAtlas: day,
  };
}
