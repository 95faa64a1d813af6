/**
 * The work plane's daylight and daylight factor from baked maps (issue 30; docs/daylight.md, "The
 * report" and "The daylight-factor view"): the one definition `luxbox bake`'s report and the 3D
 * view's DF mode both call. The grid of workPlanePoints (EN 17037's reference plane at 0.85 m,
 * 0.5 m from the walls), at each point the direct daylight as a texel's plus the gather of the
 * maps (workPlaneIlluminance), and the DF statistics of core/daylight/daylightFactor.ts over the
 * points with equal weights (each stands for spacing² of the plane).
 */
import { cieOvercastSky, groundLuminance, DEFAULT_GROUND_REFLECTANCE } from '../../../core/daylight/skies';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE, daylightFactorStatistics, type DaylightFactorStatistics } from '../../../core/daylight/daylightFactor';
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bakeScene';
import { createObjectRayCaster } from '../objects/createObjectRayCaster';
import type { ObjectAtlas, PreparedObjects } from '../objects/preparedObjects';
import { encloseShapedRoom } from '../shapedRoom/encloseShapedRoom';
import type { BakeDaylight } from './bakeDaylight';
import { daylightPointContext } from './daylightAtlasDirect';
import { daylightWindows } from './daylightWindows';
import { workPlaneIlluminance, workPlanePoints } from './workPlaneDaylight';

/** The objects' baked light the gather reads: the atlas (reflectances) and RGB lux per texel (the map as shown). */
export interface AtlasLight {
  atlas: ObjectAtlas;
  total: Float32Array;
}

/**
 * Y illuminance (lux) at the work plane's points of a shaped room (`scene` as given, not yet
 * enclosed), lit by `daylight` alone; `prepared` are the enclosed scene's objects the maps were
 * baked on. Empty when the room has no shape.
 */
export function workPlaneDaylight(scene: BakeScene, prepared: PreparedObjects, light: AtlasLight, daylight: BakeDaylight): Float64Array {
  const shape = scene.room.shape;
  if (!shape) return new Float64Array(0);
  const offset = encloseShapedRoom(scene).room.enclosure!.offset;
  const ctx = daylightPointContext(prepared, daylight, daylightWindows(shape, offset, daylight.glazing), true);
  const points = workPlanePoints(shape).map((p): Vec3 => [p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]]);
  return workPlaneIlluminance(points, ctx, createObjectRayCaster(prepared), light.atlas, light.total);
}

/** DF statistics of work-plane illuminances under an overcast sky of horizontal illuminance `outside` (lux); null without points. */
export function workPlaneDaylightFactorStatistics(lux: ArrayLike<number>, outside: number): DaylightFactorStatistics | null {
  if (lux.length === 0) return null;
  return daylightFactorStatistics(Array.from(lux, (e) => (100 * e) / outside));
}

/**
 * The ground's reflectance behind a BakeDaylight: as given, else from its luminance (ρ_g (E_sky,h +
 * E_sun,h) / π, skies.ts groundLuminance); the default where nothing lights the ground.
 */
export function groundReflectanceOf(d: BakeDaylight): number {
  if (d.groundReflectance !== undefined) return d.groundReflectance;
  const outside = (d.sky?.horizontalIlluminance ?? 0) + (d.sun ? d.sun.normalIlluminance * Math.max(0, d.sun.direction[1]) : 0);
  return outside > 0 ? (d.groundLuminance * Math.PI) / outside : DEFAULT_GROUND_REFLECTANCE;
}

/** The daylight factor's daylight: the same windows and glazing under the CIE overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE, no sun, the same ground. */
export function daylightFactorDaylight(d: BakeDaylight): BakeDaylight {
  const rho = groundReflectanceOf(d);
  return { sky: cieOvercastSky(DAYLIGHT_FACTOR_SKY_ILLUMINANCE), sun: null, groundLuminance: groundLuminance(DAYLIGHT_FACTOR_SKY_ILLUMINANCE, 0, rho), glazing: d.glazing, groundReflectance: rho };
}
