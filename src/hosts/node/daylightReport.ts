/**
 * report.json's `daylight` (docs/daylight.md, "The report"): for a scene with a sky and windows,
 * the sky and the sun's position, the daylight entering, the daylight illuminance on the work
 * plane (WORK_PLANE_HEIGHT, WALL_BAND from the walls) at the scene's date, time and place, and
 * the daylight factor under the CIE standard overcast sky — on the work plane and on the floor —
 * with EN 17037's shares (core/daylight/daylightFactor.ts). Daylight alone: a scene with
 * luminaires is baked once more without them, and once more under the overcast sky unless its
 * own sky is that sky without a sun.
 */
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE } from '../../core/daylight/daylightFactor';
import { daylightFactorStatistics, type DaylightFactorStatistics } from '../../core/daylight/daylightFactor';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import type { SceneSky } from '../../core/model/lightingScene/parseDaylight';
import type { BakeReport } from '../../engines/bake/bakeJob';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { BakeSettings } from '../../engines/bake/bakeSettings';
import { luxOf, type BakedMaps } from '../../engines/bake/bakedMaps';
import type { BakeDaylight } from '../../engines/bake/daylight/bakeDaylight';
import { bakeDaylightFor, bakeDaylightOf } from '../../engines/bake/daylight/sceneDaylight';
import { WALL_BAND, WORK_PLANE_HEIGHT, WORK_PLANE_SPACING } from '../../engines/bake/daylight/workPlaneDaylight';
import { workPlaneDaylight, workPlaneDaylightFactorStatistics } from '../../engines/bake/daylight/workPlaneDaylightFactor';
import { prepareObjectsCached } from '../../engines/bake/objects/prepareObjectsCached';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';

type Bake = (scene: BakeScene) => { maps: BakedMaps; report: BakeReport };

const round = (v: number, digits = 4): number => Number(v.toPrecision(digits));
const rounded = (s: DaylightFactorStatistics) => Object.fromEntries(Object.entries(s).map(([k, v]) => [k, typeof v === 'number' ? round(v) : v]));
const roundedOrNull = (s: DaylightFactorStatistics | null) => (s ? rounded(s) : null);

/** Work-plane illuminance (lux, Y) of a daylight-only bake's maps, at the plane's points (workPlaneDaylightFactor.ts: the 3D view's DF mode calls the same). */
function workPlane(bakeScene: BakeScene, maps: BakedMaps, daylight: BakeDaylight, settings: BakeSettings): { lux: Float64Array; points: number } {
  const enclosed = encloseShapedRoom(bakeScene);
  const prepared = prepareObjectsCached(enclosed.objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
  const lux = workPlaneDaylight(bakeScene, prepared, maps.objects!, daylight);
  return { lux, points: lux.length };
}

/** The work plane's DF statistics (unrounded) from a daylight-only bake under an overcast sky of horizontal illuminance `outside`, null without points. */
export function workPlaneDaylightFactorOfBake(bakeScene: BakeScene, maps: BakedMaps, daylight: BakeDaylight, settings: BakeSettings, outside: number): DaylightFactorStatistics | null {
  return workPlaneDaylightFactorStatistics(workPlane(bakeScene, maps, daylight, settings).lux, outside);
}

/** Daylight factors (%) of the floor's atlas texels, weighted by their coverage. */
function floorDaylightFactor(maps: BakedMaps, outside: number): DaylightFactorStatistics {
  const o = maps.objects!;
  const lux = luxOf(o.total);
  const values: number[] = [];
  const weights: number[] = [];
  for (let k = 0; k < lux.length; k++) {
    // The room's floor is the enclosure's first object (shapedRoom/roomSurfaceObjects.ts).
    if (o.atlas.reflectance[4 * k + 3] !== 1 || !(o.atlas.position[4 * k + 3] > 0)) continue;
    values.push((100 * lux[k]) / outside);
    weights.push(o.atlas.position[4 * k + 3]);
  }
  return daylightFactorStatistics(values, weights);
}

export function daylightReport(scene: LightingScene, bakeScene: BakeScene, maps: BakedMaps, report: BakeReport, settings: BakeSettings, bake: Bake): Record<string, unknown> | null {
  const own = bakeDaylightOf(scene);
  const sky = scene.daylight?.sky;
  if (!own || !sky || !bakeScene.room.shape || !report.daylight) return null;
  const daylightOnly = bakeScene.luminaires.length === 0 ? maps : bake({ ...bakeScene, luminaires: [] }).maps;
  const plane = workPlane(bakeScene, daylightOnly, own.daylight, settings);
  const overcastSky: SceneSky = { type: 'cie-overcast', horizontalIlluminance: DAYLIGHT_FACTOR_SKY_ILLUMINANCE, groundReflectance: sky.groundReflectance };
  const ownIsOvercast = sky.type === 'cie-overcast';
  const overcast = ownIsOvercast ? own : bakeDaylightFor(overcastSky, scene);
  const overcastMaps = ownIsOvercast ? daylightOnly : bake({ ...bakeScene, luminaires: [], daylight: overcast.daylight }).maps;
  const overcastPlane = ownIsOvercast ? plane : workPlane(bakeScene, overcastMaps, overcast.daylight, settings);
  const outside = overcast.conditions.skyHorizontalIlluminance;
  const c = own.conditions;
  const lux = [...plane.lux];
  return {
    sky: sky.type,
    skyHorizontalIlluminance: round(c.skyHorizontalIlluminance),
    sunHorizontalIlluminance: round(c.sunHorizontalIlluminance),
    sun: c.position ? { elevation: round(c.position.elevation, 6), azimuth: round(c.position.azimuth, 6), shining: c.sun !== null } : null,
    windows: report.daylight.windows,
    enteringFlux: { sky: round(report.daylight.skyFlux), sun: round(report.daylight.sunFlux) },
    workPlane: {
      height: WORK_PLANE_HEIGHT,
      wallBand: WALL_BAND,
      spacing: WORK_PLANE_SPACING,
      points: plane.points,
      illuminance: lux.length > 0 ? { mean: round(lux.reduce((a, b) => a + b, 0) / lux.length), min: round(Math.min(...lux)), max: round(Math.max(...lux)) } : null,
    },
    daylightFactor: {
      sky: 'cie-overcast',
      workPlane: roundedOrNull(workPlaneDaylightFactorStatistics(overcastPlane.lux, outside)),
      floor: rounded(floorDaylightFactor(overcastMaps, outside)),
    },
  };
}
