/**
 * `--date YYYY-MM-DD` and `--time HH:MM` of `luxbox render` and `luxbox probe` (docs/daylight.md,
 * "On the command line"): the scene's own sun (`sky.sun`: place, date and time) at another day or
 * clock time, so one scene file gives the shop's images at 10:00 in June and at 17:00 in December.
 * The sky is written back as the file has it (daylightJson.ts), the new date or time put in, and
 * read again by the contract's own reader (parseSky), so every rule of the file holds for the
 * override too (a real day in 1901–2099, a clear sky needs the sun above the horizon); a refusal
 * names the flag and the field.
 */
import { InputError } from '../../core/inputError';
import { skyJson } from '../../core/model/lightingScene/daylightJson';
import type { LightingScene } from '../../core/model/lightingScene/lightingScene';
import { parseSky } from '../../core/model/lightingScene/parseDaylight';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { bakeDaylightOf } from '../../engines/bake/daylight/sceneDaylight';

export const DATE_FLAG = '--date';
export const TIME_FLAG = '--time';

export interface DaylightTime {
  /** "YYYY-MM-DD". */
  date?: string;
  /** "HH:MM" or "HH:MM:SS", the clock time of the sun's time zone. */
  time?: string;
}

/** The flags as given (absent when neither is). */
export function daylightTimeOptions(options: Record<string, string>): DaylightTime | null {
  const date = options[DATE_FLAG];
  const time = options[TIME_FLAG];
  if (date === undefined && time === undefined) return null;
  return { ...(date !== undefined ? { date } : {}), ...(time !== undefined ? { time } : {}) };
}

/**
 * `input` (a loaded scene or render input) with its sun at `when`: the lighting scene's sky and
 * the bake scene's daylight both replaced. `file` names the scene in a refusal.
 */
export function withDaylightTime<T extends { scene: LightingScene; bakeScene: BakeScene }>(input: T, when: DaylightTime | null, command: string, file: string): T {
  if (!when) return input;
  const flags = [when.date !== undefined ? `${DATE_FLAG} ${when.date}` : '', when.time !== undefined ? `${TIME_FLAG} ${when.time}` : ''].filter(Boolean).join(' ');
  const sky = input.scene.daylight?.sky;
  if (!sky?.sun) throw new InputError(`${command}: ${flags}: ${file} has no sun to move (give its sky a "sun" with the place, date and time: docs/daylight.md)`);
  const json = skyJson(sky);
  const sun = { ...(json.sun as Record<string, unknown>), ...(when.date !== undefined ? { date: when.date } : {}), ...(when.time !== undefined ? { time: when.time } : {}) };
  const moved = parseSky({ ...json, sun }, `${flags} (${file})`);
  const scene: LightingScene = { ...input.scene, daylight: { ...input.scene.daylight!, sky: moved } };
  const daylight = bakeDaylightOf(scene);
  return { ...input, scene, bakeScene: { ...input.bakeScene, ...(daylight ? { daylight: daylight.daylight } : {}) } };
}
