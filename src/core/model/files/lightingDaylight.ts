/**
 * A configuration's daylight as the lighting scene's (docs/daylight.md "The contract"), which the
 * baker reads (engines/bake/daylight/sceneDaylight.ts): the sky with the sun's place, day and clock
 * time, and each window's glazing by opening index. Part of the room-shape chunk.
 *
 * A city's clock keeps its summer time (clockOffset.ts: 10:00 in Zurich on 21 June is 08:00 UTC).
 * While daylight is off, or the sun is below the horizon at that time, there is no sky: nothing of
 * daylight is baked (the windows still let light out), as at night; with daylight on, the ground's
 * reflectance stays for the daylight factor.
 */
import { cityNamed } from '../../daylight/cities';
import { clockOffsetHours } from '../../daylight/clockOffset';
import { solarPosition } from '../../daylight/solarPosition';
import type { Configuration } from '../configuration/configuration';
import { isCityPlace, type DaylightSettings } from '../configuration/daylightSettings';
import type { LightingDaylight } from '../lightingScene/lightingScene';
import type { SceneSky, SceneSun, TransmittanceValue } from '../lightingScene/parseDaylight';
import { daylightDate, daylightHours } from '../validation/daylightProblems';

/** The sun's place, day and clock time of valid settings (validate() holds), the clock's offset resolved. */
export function daylightSun(daylight: DaylightSettings): SceneSun {
  const { year, month, day } = daylightDate(daylight.date)!;
  const hours = daylightHours(daylight.time)!;
  if (isCityPlace(daylight.place)) {
    const c = cityNamed(daylight.place.city)!;
    return { latitude: c.latitude, longitude: c.longitude, timeZone: clockOffsetHours(c.ianaZone, c.timeZone, year, month, day, hours), city: c.name, year, month, day, hours };
  }
  const { latitude, longitude, timeZone } = daylight.place;
  return { latitude, longitude, timeZone, year, month, day, hours };
}

/** The sky of daylight that is on, or null when it is off or the sun is below the horizon then. */
export function daylightSky(daylight: DaylightSettings): SceneSky | null {
  if (!daylight.on) return null;
  const sun = daylightSun(daylight);
  if (solarPosition(sun, sun).elevation <= 0) return null;
  return { type: daylight.sky, groundReflectance: daylight.groundReflectance, sun };
}

/**
 * The lighting scene's daylight of a configuration: its sky and the glazing written on its windows;
 * with daylight on while the sun is down, no sky and the ground's reflectance (the daylight factor's
 * overcast sky needs no sun); null when it has none of these.
 */
export function lightingDaylight(config: Configuration): LightingDaylight | null {
  const transmittance: Record<number, TransmittanceValue> = {};
  (config.room.shape?.openings ?? []).forEach((o, i) => {
    if (o.kind === 'window' && o.transmittance !== undefined) transmittance[i] = o.transmittance;
  });
  const sky = config.daylight ? daylightSky(config.daylight) : null;
  const night = !sky && config.daylight?.on === true ? { groundReflectance: config.daylight.groundReflectance } : {};
  if (!sky && !('groundReflectance' in night) && Object.keys(transmittance).length === 0) return null;
  return { ...(sky ? { sky } : {}), windows: [], transmittance, ...night };
}
