/**
 * The configuration's daylight (issue 30, docs/daylight.md "The shopper's daylight"): whether the
 * sky and the sun light the room, the place, the day and the clock time, the sky. Types and
 * defaults only (on the first screen); its rules (validation/daylightProblems.ts), file schema
 * (files/daylightFileSchema.ts), actions (actions/daylightActions.ts) and what the baker gets
 * (files/lightingDaylight.ts) are in the room-shape chunk: windows exist only in rooms with a shape.
 */
import type { SkyType, TransmittanceValue } from '../lightingScene/parseDaylight';

export type { SkyType, TransmittanceValue };

/** A city of the short list (core/daylight/cities.ts): its coordinates, and its clock's zone with summer time (IANA). */
export interface DaylightCity {
  readonly city: string;
}

/** Coordinates and a fixed clock offset. */
export interface DaylightCoordinates {
  /** Degrees north, −90 … 90. */
  readonly latitude: number;
  /** Degrees east, −180 … 180. */
  readonly longitude: number;
  /** Hours ahead of UTC of the clock time, −12 … 14 (quarters of an hour allowed). */
  readonly timeZone: number;
}

export type DaylightPlace = DaylightCity | DaylightCoordinates;

export interface DaylightSettings {
  /** Off: the settings are kept, nothing of daylight is baked. */
  readonly on: boolean;
  readonly place: DaylightPlace;
  /** "YYYY-MM-DD", 1901 … 2099 (where the solar-position algorithm holds). */
  readonly date: string;
  /** Clock time "HH:MM" at the place (a city's with its summer time). */
  readonly time: string;
  readonly sky: SkyType;
  /** The ground outside, [0, 1). */
  readonly groundReflectance: number;
}

/** What daylight starts from before anything is set (off): Zurich at 10:00 on the longest day under a clear sky. */
export const DEFAULT_DAYLIGHT: DaylightSettings = { on: false, place: { city: 'Zurich' }, date: '2026-06-21', time: '10:00', sky: 'cie-clear', groundReflectance: 0.2 };

export function isCityPlace(place: DaylightPlace): place is DaylightCity {
  return 'city' in place;
}
