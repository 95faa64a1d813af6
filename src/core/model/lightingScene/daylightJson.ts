/**
 * The daylight fields of a lighting scene as the file writes them (docs/daylight.md, "The
 * contract"): parseSky(skyJson(s)) and parseWindows(windowJson(w)) give them back (a city stays a
 * city, its zone written as an offset; the clock time to the second).
 */
import type { SceneSky, SceneSun, SceneWindow } from './parseDaylight';

const two = (n: number): string => String(n).padStart(2, '0');

/** Hours ahead of UTC as "+HH:MM" / "-HH:MM". */
export function zoneText(hours: number): string {
  const minutes = Math.round(Math.abs(hours) * 60);
  return `${hours < 0 ? '-' : '+'}${two(Math.floor(minutes / 60))}:${two(minutes % 60)}`;
}

function sunJson(s: SceneSun): Record<string, unknown> {
  const seconds = Math.round(s.hours * 3600);
  const place = s.city !== undefined ? { city: s.city } : { latitude: s.latitude, longitude: s.longitude };
  return {
    ...place,
    timeZone: zoneText(s.timeZone),
    date: `${s.year}-${two(s.month)}-${two(s.day)}`,
    time: `${two(Math.floor(seconds / 3600))}:${two(Math.floor(seconds / 60) % 60)}:${two(seconds % 60)}`,
    ...(s.horizontalIlluminance !== undefined ? { horizontalIlluminance: s.horizontalIlluminance } : {}),
  };
}

export function skyJson(sky: SceneSky): Record<string, unknown> {
  return {
    type: sky.type,
    ...(sky.horizontalIlluminance !== undefined ? { horizontalIlluminance: sky.horizontalIlluminance } : {}),
    groundReflectance: sky.groundReflectance,
    ...(sky.sun ? { sun: sunJson(sky.sun) } : {}),
  };
}

export function windowJson(w: SceneWindow): Record<string, unknown> {
  return { wall: w.wall, u: w.u, v: w.v, width: w.width, height: w.height, transmittance: w.transmittance };
}
