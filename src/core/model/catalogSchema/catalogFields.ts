/** Field schemas every catalog section shares, and the grid test its rules use. */
import { z } from 'zod';

export const positive = z.number().finite().positive();
export const price = z.number().finite().nonnegative();
export const nonEmpty = z.string().min(1);
/**
 * A catalog text in the UI's other languages (docs/catalog-format.md, "Translations"): the entry's
 * own `name`/`label`/`description` is the fallback for a language not given.
 */
export const translations = z.strictObject({ en: nonEmpty.optional(), de: nonEmpty.optional(), fr: nonEmpty.optional(), it: nonEmpty.optional() }).optional();

/** True when x is an integer multiple of step, to within float noise (1e-6 of a step). */
export function onGrid(x: number, step: number): boolean {
  const k = x / step;
  return Math.abs(k - Math.round(k)) < 1e-6;
}
