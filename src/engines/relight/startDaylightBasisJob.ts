import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import type { BakeJob, Baker } from '../bake/createBaker';
import { daylightAtlasDirect, daylightPointContext } from '../bake/daylight/daylightAtlasDirect';
import { prepareObjectsCached } from '../bake/objects/prepareObjectsCached';
import { surfaceLayouts } from '../bake/surfaceLayout';
import type { DaylightPart } from './daylightGroups';

/**
 * A daylight group's direct basis (daylightGroups.ts): the direct daylight of its part at every
 * atlas texel, computed as the daylight bake computes it (startDaylightBakeJob.ts step 2, the same
 * prepared atlas), handed to the baker as a given direct map with no bounces, so the job's
 * read-back gives it as every basis has it: the atlas's map as the bounces read it (`emitted`) and
 * dilated as shown, and the enclosure's sinks (zero). `enclosed` is the engine's enclosed scene.
 */
export function startDaylightBasisJob(baker: Baker, enclosed: BakeScene, part: DaylightPart, basisSettings: BakeSettings): BakeJob {
  const objects = enclosed.objects ?? [];
  const prepared = prepareObjectsCached(objects, { texelSize: basisSettings.texelSize, maxAtlasSize: basisSettings.maxTextureSize });
  const { input } = part;
  const day = daylightAtlasDirect(prepared, daylightPointContext(prepared, input.daylight, input.windows, input.needsRays));
  const layouts = surfaceLayouts(enclosed.room, basisSettings.texelSize, basisSettings.maxTextureSize);
  const zero = Object.fromEntries(layouts.map((l) => [l.name, new Float32Array(l.width * l.height * 3)])) as Record<SurfaceName, Float32Array>;
  return baker.startFromDirect(enclosed.room, zero, basisSettings, { objects, direct: day.direct });
}
