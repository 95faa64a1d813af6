/**
 * The colour-filter (gel) library's index: which filters exist, their maker, number, name and kind.
 * Extracted from the lighting_filters 0.1.1 dataset by scripts/extractColourFilters.mjs into
 * src/core/colour/colour-filters.json (sources: src/core/colour/COLOUR-FILTERS-SOURCES.md,
 * docs/sources.md). The spectral curves are in a second file, loaded when a colour is first
 * computed (./colourFilterSpectra.ts, docs/colour-filters.md "Two files"): validating and listing
 * filters is all the planner's first screen needs, and the curves are ~10 KiB gzip of its budget.
 * Validated once at load so a broken file fails naming the filter and field.
 */
import { z } from 'zod/mini';
import { InputError } from '../inputError';
import libraryJson from './colour-filters.json';
import { safeParseInEnglish } from '../zodEnglish';

/** What a filter is for; the picker groups by it. */
export const FILTER_KINDS = ['cto', 'ctb', 'nd', 'colour'] as const;
export type FilterKind = (typeof FILTER_KINDS)[number];

/** Library ids: lower-case letters, digits and hyphens ('lee-204'); the spectra file uses the same. */
export const FILTER_ID_PATTERN = /^[a-z0-9-]+$/;

const filterSchema = z.strictObject({
  id: z.string().check(z.regex(FILTER_ID_PATTERN)),
  maker: z.string().check(z.minLength(1)),
  number: z.string().check(z.minLength(1)),
  name: z.string().check(z.minLength(1)),
  kind: z.enum(FILTER_KINDS),
});

const librarySchema = z.strictObject({
  formatVersion: z.literal(2),
  filters: z.array(filterSchema).check(z.minLength(1)),
});

export type ColourFilter = z.infer<typeof filterSchema>;
export type ColourFilterLibrary = z.infer<typeof librarySchema>;

/**
 * Parses one of the library's files with its schema and checks that every id is used once; an
 * InputError names the file and the field (`filters.2.kind: …`) or the repeated id.
 */
export function parseFilterFile<T>(file: string, schema: z.ZodMiniType<T>, data: unknown, entries: (parsed: T) => readonly { id: string }[]): T {
  const r = safeParseInEnglish(schema, data);
  if (!r.success) {
    const issue = r.error.issues[0];
    throw new InputError(`${file}: ${issue.path.join('.')}: ${issue.message}`);
  }
  const seen = new Set<string>();
  for (const { id } of entries(r.data)) {
    if (seen.has(id)) throw new InputError(`${file}: duplicate filter id '${id}'`);
    seen.add(id);
  }
  return r.data;
}

/** Parses index data (the JSON above, or a test's); throws InputError naming the filter and field. */
export function parseColourFilterLibrary(data: unknown): ColourFilterLibrary {
  return parseFilterFile('colour-filters.json', librarySchema, data, (library) => library.filters);
}

/** The library shipped with luxbox. */
export const COLOUR_FILTER_LIBRARY: ColourFilterLibrary = parseColourFilterLibrary(libraryJson);
const byId = new Map(COLOUR_FILTER_LIBRARY.filters.map((f) => [f.id, f]));

/** The library filter with this id, or undefined. */
export function colourFilter(id: string): ColourFilter | undefined {
  return byId.get(id);
}

/** The library filter with this id; an unknown id is an InputError naming it. */
export function findColourFilter(id: string): ColourFilter {
  const f = byId.get(id);
  if (!f) throw new InputError(`unknown colour filter '${id}' (not in the filter library)`);
  return f;
}
