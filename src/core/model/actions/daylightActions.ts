/**
 * Daylight (issue 30, docs/daylight.md "The shopper's daylight"): switching it on and off, the
 * place, day, clock time and sky (setDaylight), and a window's glazing (setWindowGlazing). Part of
 * the room-shape chunk (windows are openings of a room's shape); every result is judged by
 * validate() where the action is bound, so an impossible value (a 30 February, 25:00, an unknown
 * city, a transmittance of 1.2) is refused with the rule's own sentence.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import { cityNamed } from '../../daylight/cities';
import { GLAZING_PRESETS, type GlazingPreset } from '../../daylight/glazing';
import type { ActionDefinition } from './action';
import { ROOM_SHAPE_ACTION_LABELS } from './roomShapeActionNames';
import type { Configuration, ShapeOpening } from '../configuration/configuration';
import { DEFAULT_DAYLIGHT, isCityPlace, type DaylightCoordinates, type DaylightSettings } from '../configuration/daylightSettings';
import { SKY_TYPES } from '../lightingScene/parseDaylight';

const daylightParams = z.object({
  on: z.optional(z.boolean()),
  city: z.optional(z.string()),
  latitude: z.optional(z.number()),
  longitude: z.optional(z.number()),
  timeZone: z.optional(z.number()),
  date: z.optional(z.string()),
  time: z.optional(z.string()),
  sky: z.optional(z.enum(SKY_TYPES)),
  groundReflectance: z.optional(z.number()),
});
type DaylightParams = z.infer<typeof daylightParams>;

/** The place after the change: a city by name, or coordinates merged onto the current ones (a city's own, with its standard zone). */
function placeAfter(current: DaylightSettings['place'], p: DaylightParams): DaylightSettings['place'] {
  const coordinates = p.latitude !== undefined || p.longitude !== undefined || p.timeZone !== undefined;
  if (p.city !== undefined && coordinates) throw new InputError('give either a city or coordinates, not both', { code: 'daylightPlaceTwice' });
  if (p.city !== undefined) return { city: p.city };
  if (!coordinates) return current;
  let base: DaylightCoordinates | undefined = isCityPlace(current) ? undefined : current;
  if (!base) {
    const c = cityNamed((current as { city: string }).city);
    base = c ? { latitude: c.latitude, longitude: c.longitude, timeZone: c.timeZone } : { latitude: 0, longitude: 0, timeZone: 0 };
  }
  return { latitude: p.latitude ?? base.latitude, longitude: p.longitude ?? base.longitude, timeZone: p.timeZone ?? base.timeZone };
}

/** Sets any of the daylight's settings; the others stay (the first time: DEFAULT_DAYLIGHT's, off until `on` says so). */
export const setDaylight: ActionDefinition<DaylightParams> = {
  name: 'setDaylight',
  label: ROOM_SHAPE_ACTION_LABELS.setDaylight,
  params: daylightParams,
  perform(state, p) {
    const d = state.daylight ?? DEFAULT_DAYLIGHT;
    const daylight: DaylightSettings = {
      on: p.on ?? d.on,
      place: placeAfter(d.place, p),
      date: p.date ?? d.date,
      time: p.time ?? d.time,
      sky: p.sky ?? d.sky,
      groundReflectance: p.groundReflectance ?? d.groundReflectance,
    };
    return { ...state, daylight };
  },
};

const PRESETS = Object.keys(GLAZING_PRESETS) as [GlazingPreset, ...GlazingPreset[]];
const glazingParams = z.object({ opening: z.number().check(z.int(), z.gte(0)), transmittance: z.union([z.number(), z.enum(PRESETS)]) });

/** A window's glazing: a preset (single 0.85, double 0.75, triple 0.6) or its normal-incidence transmittance 0 … 1 (1 = open). */
export const setWindowGlazing: ActionDefinition<z.infer<typeof glazingParams>> = {
  name: 'setWindowGlazing',
  label: ROOM_SHAPE_ACTION_LABELS.setWindowGlazing,
  params: glazingParams,
  perform(state: Configuration, p) {
    const shape = state.room.shape;
    const o = shape?.openings[p.opening];
    if (!shape || !o) throw new InputError(`the room has no opening ${p.opening}`, { code: 'roomNoOpening', params: { opening: p.opening } });
    if (o.kind !== 'window') throw new InputError(`opening ${p.opening} is a ${o.kind}; only a window has glazing`, { code: 'glazing-not-window', params: { opening: p.opening, kind: o.kind } });
    const glazed: ShapeOpening = { ...o, transmittance: p.transmittance };
    return { ...state, room: { ...state.room, shape: { ...shape, openings: shape.openings.map((x, i) => (i === p.opening ? glazed : x)) } } };
  },
};
