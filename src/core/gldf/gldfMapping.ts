/**
 * The mapping file a manufacturer writes for what GLDF does not say and the rail catalog needs
 * (docs/gldf.md, "The mapping file"): per product (by its GLDF UniqueProductId) the module
 * type's id, its length on the rail, prices, roll, default CCT and beam, aiming ranges; and
 * which GLDF mountings fit the rail. Everything is optional: what is absent takes a documented
 * default, and the import report lists each value assumed.
 */
import { z } from 'zod/mini';
import { versionedDataProblem } from '../model/catalogSchema/catalogSchema';
import { parseUntrustedJson } from '../untrustedJson';
import { describeIssues, schemaFieldNames } from '../zodIssues';
import { GldfError } from './GldfError';
import { safeParseInEnglish } from '../zodEnglish';

const catalogId = z.string().check(z.regex(/^[a-z0-9][a-z0-9-]{0,63}$/, 'must be lower-case letters, digits and - (at most 64)'));
const nonEmpty = z.string().check(z.minLength(1), z.maxLength(200));
const aimRange = z.strictObject({ min: z.number(), max: z.number(), stops: z.optional(z.number().check(z.positive())) });
const translations = z.strictObject({ en: z.optional(nonEmpty), de: z.optional(nonEmpty), fr: z.optional(nonEmpty), it: z.optional(nonEmpty) });

const beamMapping = z.strictObject({
  id: z.optional(catalogId),
  label: z.optional(nonEmpty),
  labels: z.optional(translations),
  article: z.optional(nonEmpty),
  /** Degrees; turns the photometry's C0 on the rail (docs/catalog-format.md, "Rolls"). */
  roll: z.optional(z.number().check(z.gte(-180), z.lte(180))),
  price: z.optional(z.number().check(z.nonnegative())),
});

const productMapping = z.strictObject({
  id: z.optional(catalogId),
  /** Rail length the module occupies, metres. */
  length: z.optional(z.number().check(z.positive(), z.lte(10))),
  /** Price of every beam the mapping or the GLDF does not price. */
  price: z.optional(z.number().check(z.nonnegative())),
  defaultCct: z.optional(z.number().check(z.int())),
  defaultBeam: z.optional(catalogId),
  /** The head's aiming ranges (catalog `adjustable`), or false for a fixed module whatever the GLDF says. */
  adjustable: z.optional(z.union([z.literal(false), z.strictObject({ tilt: aimRange, rotation: aimRange })])),
  filterHolder: z.optional(z.boolean()),
  /** Per GLDF Photometry id: the beam this photometry becomes. */
  beams: z.optional(z.record(z.string().check(z.maxLength(200)), beamMapping)),
});

export const gldfMappingSchema = z.strictObject({
  formatVersion: z.literal(1),
  /** GLDF mountings that fit the rail ('ceiling-surface', 'ceiling-pendant', …); default both of those. */
  mountings: z.optional(z.array(z.string().check(z.regex(/^[a-z][a-z-]{0,40}$/))).check(z.minLength(1))),
  /** Per GLDF UniqueProductId. */
  products: z.optional(z.record(z.string().check(z.maxLength(200)), productMapping)),
});

export type GldfMapping = z.infer<typeof gldfMappingSchema>;
export type GldfProductMapping = z.infer<typeof productMapping>;
export type GldfBeamMapping = z.infer<typeof beamMapping>;

/** The rail's mountings when the mapping names none: a track module hangs from the ceiling, on the surface or on suspensions. */
export const DEFAULT_RAIL_MOUNTINGS: readonly string[] = ['ceiling-surface', 'ceiling-pendant'];

const FIELDS = schemaFieldNames(gldfMappingSchema);

/** Parses a mapping file's text; throws GldfError naming the file and the field. */
export function parseGldfMapping(text: string, source: string): GldfMapping {
  const data = parseUntrustedJson(text, source, (m) => new GldfError(m));
  const problem = versionedDataProblem(data, 'formatVersion', 1);
  if (problem) throw new GldfError(`${source}: ${problem}`);
  const r = safeParseInEnglish(gldfMappingSchema, data);
  if (!r.success) throw new GldfError(`${source}: ${describeIssues(r.error.issues, FIELDS)}`);
  return r.data;
}
