/**
 * The mapping file a manufacturer writes for what GLDF does not say and the rail catalog needs
 * (docs/gldf.md, "The mapping file"): per product (by its GLDF UniqueProductId) the module
 * type's id, its length on the rail, prices, roll, default CCT and beam, aiming ranges; and
 * which GLDF mountings fit the rail. Everything is optional: what is absent takes a documented
 * default, and the import report lists each value assumed.
 */
import { z } from 'zod';
import { versionedDataProblem } from '../model/catalogSchema/catalogSchema';
import { parseUntrustedJson } from '../untrustedJson';
import { describeIssues, schemaFieldNames } from '../zodIssues';
import { GldfError } from './GldfError';

const catalogId = z.string().regex(/^[a-z0-9][a-z0-9-]{0,63}$/, 'must be lower-case letters, digits and - (at most 64)');
const nonEmpty = z.string().min(1).max(200);
const aimRange = z.strictObject({ min: z.number().finite(), max: z.number().finite(), stops: z.number().finite().positive().optional() });
const translations = z.strictObject({ en: nonEmpty.optional(), de: nonEmpty.optional(), fr: nonEmpty.optional(), it: nonEmpty.optional() });

const beamMapping = z.strictObject({
  id: catalogId.optional(),
  label: nonEmpty.optional(),
  labels: translations.optional(),
  article: nonEmpty.optional(),
  /** Degrees; turns the photometry's C0 on the rail (docs/catalog-format.md, "Rolls"). */
  roll: z.number().finite().min(-180).max(180).optional(),
  price: z.number().finite().nonnegative().optional(),
});

const productMapping = z.strictObject({
  id: catalogId.optional(),
  /** Rail length the module occupies, metres. */
  length: z.number().finite().positive().max(10).optional(),
  /** Price of every beam the mapping or the GLDF does not price. */
  price: z.number().finite().nonnegative().optional(),
  defaultCct: z.number().int().optional(),
  defaultBeam: catalogId.optional(),
  /** The head's aiming ranges (catalog `adjustable`), or false for a fixed module whatever the GLDF says. */
  adjustable: z.union([z.literal(false), z.strictObject({ tilt: aimRange, rotation: aimRange })]).optional(),
  filterHolder: z.boolean().optional(),
  /** Per GLDF Photometry id: the beam this photometry becomes. */
  beams: z.record(z.string().max(200), beamMapping).optional(),
});

export const gldfMappingSchema = z.strictObject({
  formatVersion: z.literal(1),
  /** GLDF mountings that fit the rail ('ceiling-surface', 'ceiling-pendant', …); default both of those. */
  mountings: z
    .array(z.string().regex(/^[a-z][a-z-]{0,40}$/))
    .min(1)
    .optional(),
  /** Per GLDF UniqueProductId. */
  products: z.record(z.string().max(200), productMapping).optional(),
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
  const r = gldfMappingSchema.safeParse(data);
  if (!r.success) throw new GldfError(`${source}: ${describeIssues(r.error.issues, FIELDS)}`);
  return r.data;
}
