/** Field schemas every catalog section shares, and the grid test its rules use. */
import { z } from 'zod/mini';

export const positive = z.number().check(z.positive());
export const price = z.number().check(z.nonnegative());
export const nonEmpty = z.string().check(z.minLength(1));
/**
 * A catalog text in the UI's other languages (docs/catalog-format.md, "Translations"): the entry's
 * own `name`/`label`/`description` is the fallback for a language not given.
 */
export const translations = z.optional(z.strictObject({ en: z.optional(nonEmpty), de: z.optional(nonEmpty), fr: z.optional(nonEmpty), it: z.optional(nonEmpty) }));

/** True when x is an integer multiple of step, to within float noise (1e-6 of a step). */
export function onGrid(x: number, step: number): boolean {
  const k = x / step;
  return Math.abs(k - Math.round(k)) < 1e-6;
}
