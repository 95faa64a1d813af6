/**
 * validate()'s rules for the configuration's daylight and the windows' glazing (issue 30,
 * docs/daylight.md "The shopper's daylight"); part of the room-shape chunk, which validate() asks
 * through roomShapeSupport. The sun may be below the horizon (a clock time after sunset is a
 * valid state: nothing of the sun is baked then), so unlike the lighting scene's reader
 * (parseDaylight.ts) no rule depends on where the sun stands.
 */
import { cityNamed } from '../../daylight/cities';
import { GLAZING_PRESETS } from '../../daylight/glazing';
import type { Configuration } from '../configuration/configuration';
import type { DaylightSettings } from '../configuration/daylightSettings';
import type { Problem } from '../configuration/problem';
import { DAYLIGHT_LIMITS, SKY_TYPES } from '../lightingScene/parseDaylight';

const DATE = /^(\d{4})-(\d{2})-(\d{2})$/;
const TIME = /^(\d{2}):(\d{2})$/;
const finite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);
const daysInMonth = (y: number, m: number): number => new Date(Date.UTC(y, m, 0)).getUTCDate();

/** The date "YYYY-MM-DD" as numbers, or null when it is not a day of the calendar within the algorithm's years. */
export function daylightDate(date: string): { year: number; month: number; day: number } | null {
  const d = DATE.exec(date);
  if (!d) return null;
  const [year, month, day] = [Number(d[1]), Number(d[2]), Number(d[3])];
  if (year < DAYLIGHT_LIMITS.minYear || year > DAYLIGHT_LIMITS.maxYear || month < 1 || month > 12 || day < 1 || day > daysInMonth(year, month)) return null;
  return { year, month, day };
}

/** The clock time "HH:MM" in hours (10.5 for "10:30"), or null. */
export function daylightHours(time: string): number | null {
  const t = TIME.exec(time);
  if (!t || Number(t[1]) > 23 || Number(t[2]) > 59) return null;
  return Number(t[1]) + Number(t[2]) / 60;
}

function placeProblems(place: DaylightSettings['place']): Problem[] {
  if ('city' in place) {
    return cityNamed(place.city) ? [] : [{ code: 'daylight-city', path: 'daylight.place.city', message: `'${place.city}' is not a city of the list; give latitude, longitude and time zone instead`, params: { city: place.city } }];
  }
  const out: Problem[] = [];
  const range = (code: string, field: 'latitude' | 'longitude' | 'timeZone', what: string, min: number, max: number, unit: string) => {
    const v = place[field];
    if (!finite(v) || v < min || v > max) out.push({ code, path: `daylight.place.${field}`, message: `${what} must be between ${min} and ${max} ${unit} (got ${String(v)})`, params: { min, max, value: String(v) } });
  };
  range('daylight-latitude', 'latitude', 'the latitude', -90, 90, '°');
  range('daylight-longitude', 'longitude', 'the longitude', -180, 180, '°');
  range('daylight-time-zone', 'timeZone', 'the time zone', -12, 14, 'h');
  return out;
}

/** The daylight's own rules, each with its path under `daylight`. */
export function daylightProblems(daylight: DaylightSettings): Problem[] {
  const out = placeProblems(daylight.place);
  if (!daylightDate(daylight.date))
    out.push({
      code: 'daylight-date',
      path: 'daylight.date',
      message: `'${daylight.date}' is not a day between ${DAYLIGHT_LIMITS.minYear} and ${DAYLIGHT_LIMITS.maxYear} written YYYY-MM-DD`,
      params: { date: daylight.date, min: DAYLIGHT_LIMITS.minYear, max: DAYLIGHT_LIMITS.maxYear },
    });
  if (daylightHours(daylight.time) === null) out.push({ code: 'daylight-time', path: 'daylight.time', message: `'${daylight.time}' is not a clock time 00:00 to 23:59`, params: { time: daylight.time } });
  if (!(SKY_TYPES as readonly string[]).includes(daylight.sky)) out.push({ code: 'daylight-sky', path: 'daylight.sky', message: `'${daylight.sky}' is not a sky: uniform, cie-overcast or cie-clear`, params: { sky: daylight.sky } });
  const g = daylight.groundReflectance;
  if (!finite(g) || g < 0 || g >= 1) out.push({ code: 'daylight-ground', path: 'daylight.groundReflectance', message: `the ground's reflectance must be at least 0 and below 1 (got ${String(g)})`, params: { value: String(g) } });
  return out;
}

/** Glazing only on windows, and a preset or a number 0 … 1 (1 = open). */
export function glazingProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  (config.room.shape?.openings ?? []).forEach((o, i) => {
    const t = o.transmittance;
    if (t === undefined) return;
    const path = `room.shape.openings[${i}].transmittance`;
    if (o.kind !== 'window') out.push({ code: 'glazing-not-window', path, message: `opening ${i} is a ${o.kind}; only a window has glazing`, params: { opening: i, kind: o.kind } });
    else if (typeof t === 'string' ? !(t in GLAZING_PRESETS) : !finite(t) || t < 0 || t > 1)
      out.push({ code: 'window-glazing', path, message: `the glazing of window ${i} must be single, double, triple or a transmittance from 0 to 1 (got ${String(t)})`, params: { opening: i, value: String(t) } });
  });
  return out;
}

/** Every daylight rule of a configuration: its daylight's, then each window's glazing. */
export function configurationDaylightProblems(config: Configuration): Problem[] {
  return [...(config.daylight ? daylightProblems(config.daylight) : []), ...glazingProblems(config)];
}
