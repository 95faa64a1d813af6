/**
 * A configuration file's `daylight` (version 10, docs/daylight.md "The shopper's daylight"): the
 * structure, strict (an unknown field is refused, naming it). The ranges and the calendar are
 * validate()'s (validation/daylightProblems.ts). Part of the room-shape chunk: the file schema
 * takes `daylight` as it comes (sceneFileSchema.ts) and the reader asks readDaylight.
 */
import { z } from 'zod/mini';
import type { CodedText } from '../../inputError';
import { safeParseInEnglish } from '../../zodEnglish';
import { describeIssueCoded, schemaFieldNames } from '../../zodIssues';
import type { DaylightSettings } from '../configuration/daylightSettings';
import { SKY_TYPES } from '../lightingScene/parseDaylight';
import { GLAZING_PRESETS, type GlazingPreset } from '../../daylight/glazing';

const place = z.union([z.strictObject({ city: z.string().check(z.maxLength(100)) }), z.strictObject({ latitude: z.number(), longitude: z.number(), timeZone: z.number() })]);

export const daylightFileSchema = z.strictObject({
  on: z.boolean(),
  place,
  date: z.string().check(z.maxLength(10)),
  time: z.string().check(z.maxLength(5)),
  sky: z.enum(SKY_TYPES),
  groundReflectance: z.number(),
});

/** A window's glazing in a file: a preset name or a number (its range is validate()'s). */
export const transmittanceFileSchema = z.union([z.number(), z.enum(Object.keys(GLAZING_PRESETS) as [GlazingPreset, ...GlazingPreset[]])]);

const FIELD_NAMES = schemaFieldNames(daylightFileSchema);

/** The daylight as read, or its first problem as a coded sentence at its path under `prefix` (configuration.daylight). */
export function readDaylight(value: unknown, prefix: readonly PropertyKey[]): { daylight: DaylightSettings } | { problem: CodedText } {
  const r = safeParseInEnglish(daylightFileSchema, value);
  if (!r.success) return { problem: describeIssueCoded(r.error.issues, FIELD_NAMES, prefix) };
  return { daylight: r.data };
}
