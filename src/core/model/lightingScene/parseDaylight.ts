/**
 * The daylight part of the lighting scene's contract (docs/scene-format.md, "Version 2" and
 * "Daylight"; issue 30), parsed and checked but not yet read by parseLightingScene, which keeps
 * refusing `windows` and `sky` as "not baked yet" until the baker supports them (then it calls
 * parseDaylight for a version-2 file and parseOpeningGlazing for a version-3 room's openings).
 *
 * - `windows[]` (version 2, box rooms): `wall` by name, `u`, `v` the lower-left corner in the
 *   wall's map coordinates, `width`, `height`, `transmittance` (a number 0 … 1, 1 = open, or
 *   "single" | "double" | "triple"; default "double").
 * - `sky`: `type` "uniform" | "cie-overcast" | "cie-clear", optional `horizontalIlluminance` (lux,
 *   from the sky alone), `groundReflectance` (default 0.2), `sun` (the place, date and clock time,
 *   optional `horizontalIlluminance` of the direct sun).
 * - version 3: `transmittance` on `room.openings[i]` of kind "window".
 *
 * Every refusal is one line `source: path: problem`, the path as the author wrote it.
 */
import { z } from 'zod/mini';
import { CITIES, cityNamed } from '../../daylight/cities';
import { GLAZING_PRESETS, glazingFrom, type Glazing, type GlazingPreset } from '../../daylight/glazing';
import { DEFAULT_GROUND_REFLECTANCE } from '../../daylight/skies';
import { solarPosition } from '../../daylight/solarPosition';
import { excerpt } from '../../untrustedJson';
import { describeIssues, schemaFieldNames, suggestField } from '../../zodIssues';
import { LightingSceneError } from './lightingSceneError';
import { safeParseInEnglish } from '../../zodEnglish';

export const DAYLIGHT_LIMITS = {
  maxWindows: 100,
  /** Lux: the brightest horizontal illuminance from the sky alone or from the sun (a clear noon in the tropics is ~110 klx). */
  maxIlluminance: 150_000,
  minYear: 1901,
  maxYear: 2099,
} as const;

export const WINDOW_WALLS = ['ceiling', 'north', 'south', 'west', 'east'] as const;
export type WindowWall = (typeof WINDOW_WALLS)[number];
export const SKY_TYPES = ['uniform', 'cie-overcast', 'cie-clear'] as const;
export type SkyType = (typeof SKY_TYPES)[number];

/** The glazing as written: a normal-incidence number (1 = open) or a preset name. */
export type TransmittanceValue = number | GlazingPreset;
export const DEFAULT_TRANSMITTANCE: GlazingPreset = 'double';

export interface SceneWindow {
  wall: WindowWall;
  u: number;
  v: number;
  width: number;
  height: number;
  transmittance: TransmittanceValue;
  glazing: Glazing;
}

export interface SceneSun {
  latitude: number;
  longitude: number;
  /** Hours ahead of UTC. */
  timeZone: number;
  /** The city it came from, when named. */
  city?: string;
  year: number;
  month: number;
  day: number;
  /** Clock hours (12.5 = 12:30). */
  hours: number;
  /** Direct sun on a horizontal plane, lux; absent: from the IES model (docs/daylight.md). */
  horizontalIlluminance?: number;
}

export interface SceneSky {
  type: SkyType;
  /** From the sky alone, lux; absent: the IES model when a sun is up, else 10 000 lx. */
  horizontalIlluminance?: number;
  groundReflectance: number;
  sun?: SceneSun;
}

export interface SceneDaylight {
  windows: SceneWindow[];
  sky?: SceneSky;
}

const show = (value: unknown): string => excerpt(value);
const finite = z.number({ error: (i) => (i.input === undefined ? 'is missing' : `must be a number, got ${show(i.input)}`) }).check(z.refine(Number.isFinite, 'must be a finite number'));
const atLeastZero = finite.check(z.refine((v) => v >= 0, { error: (i) => `${show(i.input)} m is negative` }));
const positive = finite.check(z.refine((v) => v > 0, { error: (i) => `${show(i.input)} m must be greater than 0` }));
const illuminance = finite.check(z.refine((v) => v > 0 && v <= DAYLIGHT_LIMITS.maxIlluminance, { error: (i) => `${show(i.input)} lx is outside (0, ${DAYLIGHT_LIMITS.maxIlluminance}] lx` }));
const PRESETS = Object.keys(GLAZING_PRESETS) as GlazingPreset[];
const transmittance = z.union([finite.check(z.refine((v) => v >= 0 && v <= 1, { error: (i) => `transmittance ${show(i.input)} is outside 0 … 1 (1 = an open window)` })), z.enum(PRESETS as [GlazingPreset, ...GlazingPreset[]])], {
  error: (i) => `must be a number in 0 … 1 or "single", "double" or "triple", got ${show(i.input)}`,
});

const windowSchema = z.strictObject(
  {
    wall: z.string({ error: (i) => (i.input === undefined ? 'is missing' : `must be a wall name, got ${show(i.input)}`) }).check(
      z.refine((w) => (WINDOW_WALLS as readonly string[]).includes(w), {
        error: (i) => (i.input === 'floor' ? 'a window in the floor sees no sky (ceiling, north, south, west or east)' : `${show(i.input)} is not a wall: ceiling, north, south, west or east`),
      }),
    ),
    u: atLeastZero,
    v: atLeastZero,
    width: positive,
    height: positive,
    transmittance: z.optional(transmittance),
  },
  { error: 'must be an object' },
);

const DATE = /^(\d{4})-(\d{2})-(\d{2})$/;
const TIME = /^(\d{2}):(\d{2})(?::(\d{2}))?$/;
const ZONE = /^(?:Z|([+-])(\d{2}):(\d{2}))$/;

const sunSchema = z.strictObject(
  {
    city: z.optional(z.string({ error: 'must be a city name' })),
    latitude: z.optional(finite.check(z.refine((v) => v >= -90 && v <= 90, { error: (i) => `${show(i.input)}° is outside −90 … 90° (north positive)` }))),
    longitude: z.optional(finite.check(z.refine((v) => v >= -180 && v <= 180, { error: (i) => `${show(i.input)}° is outside −180 … 180° (east positive)` }))),
    timeZone: z.optional(z.string({ error: 'must be an offset like "+01:00" (hours ahead of UTC)' })),
    date: z.string({ error: (i) => (i.input === undefined ? 'is missing (YYYY-MM-DD)' : 'must be a date "YYYY-MM-DD"') }),
    time: z.string({ error: (i) => (i.input === undefined ? 'is missing (HH:MM)' : 'must be a clock time "HH:MM" or "HH:MM:SS"') }),
    horizontalIlluminance: z.optional(illuminance),
  },
  { error: (i) => (i.input === undefined ? 'is missing' : 'must be an object') },
);

const skySchema = z.strictObject(
  {
    type: z.string({ error: (i) => (i.input === undefined ? 'is missing ("uniform", "cie-overcast" or "cie-clear")' : `must be a sky type, got ${show(i.input)}`) }).check(
      z.refine((t) => (SKY_TYPES as readonly string[]).includes(t), {
        error: (i) => `${show(i.input)} is not a sky type: "uniform", "cie-overcast" or "cie-clear"`,
      }),
    ),
    horizontalIlluminance: z.optional(illuminance),
    groundReflectance: z.optional(finite.check(z.refine((v) => v >= 0 && v < 1, { error: (i) => `ground reflectance ${show(i.input)} is outside [0, 1)` }))),
    sun: z.optional(sunSchema),
  },
  { error: 'must be an object' },
);

const FIELD_NAMES = new Set([...schemaFieldNames(skySchema), ...schemaFieldNames(windowSchema)]);

/** A refusal `source: path: problem`. */
const refuse = (source: string, path: string, problem: string): never => {
  throw new LightingSceneError(`${source}: ${path}: ${problem}`);
};

/** Zod's first problem as `source: path: problem`, the path under `prefix`. */
function parseWith<T>(schema: z.ZodMiniType<T>, json: unknown, source: string, prefix: PropertyKey[]): T {
  const r = safeParseInEnglish(schema, json);
  if (!r.success) throw new LightingSceneError(`${source}: ${describeIssues(r.error.issues, FIELD_NAMES, prefix)}`);
  return r.data;
}

/** The extents (m) of a box wall's map: u along, v up (docs/scene-format.md "Version 2"). */
function wallExtents(wall: WindowWall, room: { width: number; height: number; depth: number }): { u: number; v: number; uAxis: string; vAxis: string } {
  if (wall === 'ceiling') return { u: room.width, v: room.depth, uAxis: 'x', vAxis: 'z' };
  if (wall === 'north' || wall === 'south') return { u: room.width, v: room.height, uAxis: 'x', vAxis: 'y' };
  return { u: room.depth, v: room.height, uAxis: 'z', vAxis: 'y' };
}

/** The room's box when it is one with finite numbers (the room's own reader reports anything else). */
function boxOf(room: unknown): { width: number; height: number; depth: number } | null {
  if (typeof room !== 'object' || room === null) return null;
  const r = room as Record<string, unknown>;
  const [width, height, depth] = [r.width, r.height, r.depth];
  return typeof width === 'number' && typeof height === 'number' && typeof depth === 'number' && [width, height, depth].every(Number.isFinite) ? { width, height, depth } : null;
}

/** Version-2 `windows` of a box room: structure, then each inside its wall, then no two overlapping. */
export function parseWindows(json: unknown, room: unknown, source: string): SceneWindow[] {
  if (!Array.isArray(json)) return refuse(source, 'windows', 'must be an array');
  if (json.length > DAYLIGHT_LIMITS.maxWindows) return refuse(source, 'windows', `more than ${DAYLIGHT_LIMITS.maxWindows} windows`);
  const windows = json.map((w, i): SceneWindow => {
    const p = parseWith(windowSchema, w, source, ['windows', i]);
    const t = p.transmittance ?? DEFAULT_TRANSMITTANCE;
    return { wall: p.wall as WindowWall, u: p.u, v: p.v, width: p.width, height: p.height, transmittance: t, glazing: glazingFrom(t) };
  });
  const box = boxOf(room);
  if (box) {
    windows.forEach((w, i) => {
      const ext = wallExtents(w.wall, box);
      const name = w.wall === 'ceiling' ? 'the ceiling' : `the ${w.wall} wall`;
      if (w.u + w.width > ext.u + 1e-9) refuse(source, `windows[${i}].width`, `the window reaches from ${w.u} to ${w.u + w.width} m along ${name} (u = ${ext.uAxis}), which ends at ${ext.u} m`);
      if (w.v + w.height > ext.v + 1e-9) refuse(source, `windows[${i}].height`, `the window reaches from ${w.v} to ${w.v + w.height} m up ${name} (v = ${ext.vAxis}), which ends at ${ext.v} m`);
    });
  }
  windows.forEach((w, i) => {
    for (let j = 0; j < i; j++) {
      const o = windows[j];
      if (o.wall !== w.wall) continue;
      const apart = w.u >= o.u + o.width || o.u >= w.u + w.width || w.v >= o.v + o.height || o.v >= w.v + w.height;
      if (!apart) refuse(source, `windows[${i}]`, `overlaps windows[${j}] on ${w.wall === 'ceiling' ? 'the ceiling' : `the ${w.wall} wall`} (windows may touch, not overlap)`);
    }
  });
  return windows;
}

const daysInMonth = (y: number, m: number): number => new Date(Date.UTC(y, m, 0)).getUTCDate();

function parseSun(raw: z.infer<typeof sunSchema>, source: string): SceneSun {
  const at = (field: string) => `sky.sun.${field}`;
  const d = DATE.exec(raw.date);
  if (!d) return refuse(source, at('date'), `${show(raw.date)} is not a date "YYYY-MM-DD"`);
  const [year, month, day] = [Number(d[1]), Number(d[2]), Number(d[3])];
  if (year < DAYLIGHT_LIMITS.minYear || year > DAYLIGHT_LIMITS.maxYear) refuse(source, at('date'), `year ${year} is outside ${DAYLIGHT_LIMITS.minYear} … ${DAYLIGHT_LIMITS.maxYear} (where the solar-position algorithm holds)`);
  if (month < 1 || month > 12 || day < 1 || day > daysInMonth(year, month)) refuse(source, at('date'), `${show(raw.date)} is not a day of the calendar`);
  const t = TIME.exec(raw.time);
  if (!t) return refuse(source, at('time'), `${show(raw.time)} is not a clock time "HH:MM" or "HH:MM:SS"`);
  const [hh, mm, ss] = [Number(t[1]), Number(t[2]), Number(t[3] ?? 0)];
  if (hh > 23 || mm > 59 || ss > 59) refuse(source, at('time'), `${show(raw.time)} is not a clock time (00:00 … 23:59:59)`);
  let timeZone: number | undefined;
  if (raw.timeZone !== undefined) {
    const z = ZONE.exec(raw.timeZone);
    if (!z) return refuse(source, at('timeZone'), `${show(raw.timeZone)} is not an offset like "+01:00" or "-05:00" (hours ahead of UTC)`);
    timeZone = z[1] === undefined ? 0 : (z[1] === '-' ? -1 : 1) * (Number(z[2]) + Number(z[3]) / 60);
    if (Number(z[3]) > 59 || timeZone < -12 || timeZone > 14) refuse(source, at('timeZone'), `${show(raw.timeZone)} is outside −12:00 … +14:00`);
  }
  let latitude = raw.latitude;
  let longitude = raw.longitude;
  let city: string | undefined;
  if (raw.city !== undefined) {
    const c = cityNamed(raw.city);
    if (!c) {
      const hint = suggestField(
        raw.city,
        CITIES.map((x) => x.name),
      );
      return refuse(source, at('city'), `unknown city ${show(raw.city)}${hint ? ` (did you mean '${hint}'?)` : ''}; give latitude, longitude and timeZone instead`);
    }
    if (latitude !== undefined || longitude !== undefined) refuse(source, at(latitude !== undefined ? 'latitude' : 'longitude'), 'give either a city or latitude and longitude, not both');
    [latitude, longitude, city] = [c.latitude, c.longitude, c.name];
    // A city's zone is its standard time; a timeZone given beside it says the clock's (summer time).
    timeZone ??= c.timeZone;
  }
  for (const [field, value] of [
    ['latitude', latitude],
    ['longitude', longitude],
    ['timeZone', timeZone],
  ] as const) {
    if (value === undefined) refuse(source, at(field), 'is missing (or name a city)');
  }
  return {
    latitude: latitude as number,
    longitude: longitude as number,
    timeZone: timeZone as number,
    ...(city !== undefined ? { city } : {}),
    year,
    month,
    day,
    hours: hh + mm / 60 + ss / 3600,
    ...(raw.horizontalIlluminance !== undefined ? { horizontalIlluminance: raw.horizontalIlluminance } : {}),
  };
}

/** `sky`: structure, then the rules across its fields (a clear sky needs the sun; an overcast one has no direct sun; no sunlight at night). */
export function parseSky(json: unknown, source: string): SceneSky {
  const raw = parseWith(skySchema, json, source, ['sky']);
  const type = raw.type as SkyType;
  const sun = raw.sun ? parseSun(raw.sun, source) : undefined;
  if (type === 'cie-clear' && !sun) refuse(source, 'sky.sun', "is missing: a clear sky needs the sun's place, date and time");
  if (sun) {
    const position = solarPosition(sun, sun);
    if (sun.horizontalIlluminance !== undefined && type === 'cie-overcast') refuse(source, 'sky.sun.horizontalIlluminance', 'an overcast sky has no direct sun (its position is only reported)');
    if (sun.horizontalIlluminance !== undefined && position.elevation <= 0) refuse(source, 'sky.sun.horizontalIlluminance', `the sun is below the horizon then (elevation ${position.elevation.toFixed(1)}°)`);
    if (type === 'cie-clear' && position.elevation <= 0) refuse(source, 'sky.sun.time', `the sun is below the horizon then (elevation ${position.elevation.toFixed(1)}°): a clear sky needs it up`);
  }
  return {
    type,
    ...(raw.horizontalIlluminance !== undefined ? { horizontalIlluminance: raw.horizontalIlluminance } : {}),
    groundReflectance: raw.groundReflectance ?? DEFAULT_GROUND_REFLECTANCE,
    ...(sun ? { sun } : {}),
  };
}

/** The daylight fields of a version-2 scene (`windows`, `sky`; the room for the windows' walls). */
export function parseDaylight(doc: { windows?: unknown; sky?: unknown; room?: unknown }, source: string): SceneDaylight {
  const windows = doc.windows === undefined ? [] : parseWindows(doc.windows, doc.room, source);
  return { windows, ...(doc.sky !== undefined ? { sky: parseSky(doc.sky, source) } : {}) };
}

/**
 * `transmittance` on a version-3 room's openings (`room.openings[i]`): only a window has glazing;
 * its value as for version-2 windows. Returns the glazing per opening index for the windows
 * (default "double"); doors and plain openings have none. The room's own schema checks the rest.
 */
export function parseOpeningGlazing(openings: unknown, source: string): Map<number, Glazing> {
  const out = new Map<number, Glazing>();
  for (const [i, t] of parseOpeningTransmittance(openings, source)) out.set(i, glazingFrom(t ?? DEFAULT_TRANSMITTANCE));
  return out;
}

/** `transmittance` as written on each window opening (undefined where a window gives none); refusals as parseOpeningGlazing's. */
export function parseOpeningTransmittance(openings: unknown, source: string): Map<number, TransmittanceValue | undefined> {
  const out = new Map<number, TransmittanceValue | undefined>();
  if (!Array.isArray(openings)) return out;
  openings.forEach((o, i) => {
    if (typeof o !== 'object' || o === null) return;
    const rec = o as Record<string, unknown>;
    const path = `room.openings[${i}].transmittance`;
    if (rec.kind !== 'window') {
      if ('transmittance' in rec) refuse(source, path, `only a window has glazing (this opening is ${typeof rec.kind === 'string' ? `a ${excerpt(rec.kind).replace(/^"|"$/g, '')}` : 'not a window'})`);
      return;
    }
    if (!('transmittance' in rec)) {
      out.set(i, undefined);
      return;
    }
    const r = safeParseInEnglish(transmittance, rec.transmittance);
    if (!r.success) refuse(source, path, r.error.issues[0].message);
    else out.set(i, r.data);
  });
  return out;
}
