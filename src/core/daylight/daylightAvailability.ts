/**
 * Horizontal illuminance from the sun and the sky for a solar elevation and a day of the year
 * when the scene does not give them: the IES recommended practice for the calculation of
 * daylight availability (J. Illum. Eng. Soc. 13(4), 381–392, 1984; the IESNA Lighting Handbook,
 * 9th ed., chapter 8, repeats it). Mean design values, not a forecast:
 *
 *   E_xt = E_sc (1 + 0.034 cos(2π (J − 2) / 365)),  E_sc = 127.5 klx (solar illuminance constant)
 *   E_dn = E_xt exp(−c m),  m = 1 / sin α (relative air mass),  c = 0.21 clear, 0.80 partly cloudy
 *   E_sun,h = E_dn sin α
 *   E_sky,h = A + B sin^C α:  clear 0.8 + 15.5 sin^0.5 α klx, partly cloudy 0.3 + 45.0 sin α,
 *   overcast 0.3 + 21.0 sin α (no direct sun).
 *
 * α is the solar elevation; at or below the horizon everything is 0 (twilight is not modelled).
 */

export type SkyCondition = 'clear' | 'partly-cloudy' | 'overcast';

export const SOLAR_ILLUMINANCE_CONSTANT = 127_500;

const MODEL: Record<SkyCondition, { extinction: number | null; a: number; b: number; c: number }> = {
  clear: { extinction: 0.21, a: 800, b: 15_500, c: 0.5 },
  'partly-cloudy': { extinction: 0.8, a: 300, b: 45_000, c: 1 },
  overcast: { extinction: null, a: 300, b: 21_000, c: 1 },
};

export interface DaylightAvailability {
  /** Extraterrestrial illuminance normal to the sun's rays, lux. */
  extraterrestrial: number;
  /** Direct sun on a plane normal to its rays, lux. */
  sunNormal: number;
  /** Direct sun on a horizontal plane, lux. */
  sunHorizontal: number;
  /** Sky alone on an unobstructed horizontal plane, lux. */
  skyHorizontal: number;
}

/** The IES (1984) daylight availability for a solar elevation (degrees) and a day of the year (1 … 366). */
export function daylightAvailability(elevation: number, dayOfYear: number, condition: SkyCondition): DaylightAvailability {
  const extraterrestrial = SOLAR_ILLUMINANCE_CONSTANT * (1 + 0.034 * Math.cos((2 * Math.PI * (dayOfYear - 2)) / 365));
  const sinAlt = Math.sin((elevation * Math.PI) / 180);
  if (!(sinAlt > 0)) return { extraterrestrial, sunNormal: 0, sunHorizontal: 0, skyHorizontal: 0 };
  const m = MODEL[condition];
  const sunNormal = m.extinction === null ? 0 : extraterrestrial * Math.exp(-m.extinction / sinAlt);
  return { extraterrestrial, sunNormal, sunHorizontal: sunNormal * sinAlt, skyHorizontal: m.a + m.b * sinAlt ** m.c };
}
