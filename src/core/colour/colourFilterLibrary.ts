/**
 * The colour-filter (gel) library: spectral transmission curves published by the manufacturers,
 * extracted from the lighting_filters 0.1.1 dataset by scripts/extractColourFilters.mjs into
 * src/core/catalog/colour-filters.json (sources: src/core/catalog/COLOUR-FILTERS-SOURCES.md,
 * docs/sources.md). Validated once at load so a broken file fails naming the filter and field.
 * The JSON is plain data without imports, so reading it from here adds no folder dependency.
 */
import { z } from 'zod';
import { InputError } from '../inputError';
import { CIE1931_2DEG, CIE1931_START_NM, CIE1931_STEP_NM } from '../photometry/cieCmf1931';
import libraryJson from '../catalog/colour-filters.json';

/** What a filter is for; the picker groups by it. */
export const FILTER_KINDS = ['cto', 'ctb', 'nd', 'colour'] as const;
export type FilterKind = (typeof FILTER_KINDS)[number];

const statedSchema = z.strictObject({ x: z.number().min(0).max(1), y: z.number().min(0).max(1), Y: z.number().min(0).max(100) });

const filterSchema = z
  .strictObject({
    id: z.string().regex(/^[a-z0-9-]+$/),
    maker: z.string().min(1),
    number: z.string().min(1),
    name: z.string().min(1),
    kind: z.enum(FILTER_KINDS),
    /** First wavelength of `transmission`, nm; on the CMF grid (380 + 5k). */
    startNm: z.number().int(),
    stepNm: z.literal(5),
    /** Spectral transmittance τ(λ), 0..1, from startNm in 5 nm steps, as published. */
    transmission: z.array(z.number().min(0).max(1)).min(2),
    /** CIE x, y, Y (Y in per cent) the dataset states under its source A and source C. */
    stated: z.strictObject({ sourceA: statedSchema.optional(), sourceC: statedSchema.optional() }),
    source: z.string().url(),
    datasetKey: z.string().min(1),
  })
  .superRefine((f, ctx) => {
    const end = f.startNm + f.stepNm * (f.transmission.length - 1);
    if ((f.startNm - CIE1931_START_NM) % CIE1931_STEP_NM !== 0 || f.startNm < CIE1931_START_NM) ctx.addIssue({ code: 'custom', path: ['startNm'], message: 'must lie on the 380–780 nm, 5 nm grid' });
    if (end > LAST_NM) ctx.addIssue({ code: 'custom', path: ['transmission'], message: `reaches ${end} nm, past ${LAST_NM} nm` });
  });

const LAST_NM = CIE1931_START_NM + CIE1931_STEP_NM * (CIE1931_2DEG.length - 1);

const librarySchema = z.strictObject({
  formatVersion: z.literal(1),
  dataset: z.strictObject({ name: z.string(), url: z.string().url(), licence: z.string(), sha256: z.string().regex(/^[0-9a-f]{64}$/) }),
  filters: z.array(filterSchema).min(1),
});

export type ColourFilter = z.infer<typeof filterSchema>;
export type ColourFilterLibrary = z.infer<typeof librarySchema>;

/** Parses library data (the JSON above, or a test's); throws InputError naming the filter and field. */
export function parseColourFilterLibrary(data: unknown): ColourFilterLibrary {
  const r = librarySchema.safeParse(data);
  if (!r.success) {
    const issue = r.error.issues[0];
    throw new InputError(`colour-filters.json: ${issue.path.join('.')}: ${issue.message}`);
  }
  const seen = new Set<string>();
  for (const f of r.data.filters) {
    if (seen.has(f.id)) throw new InputError(`colour-filters.json: duplicate filter id '${f.id}'`);
    seen.add(f.id);
  }
  return r.data;
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

/**
 * τ(λ) on the colour-matching functions' grid, 380–780 nm in 5 nm steps (81 values). The published
 * curves stop short of the CMF range (LEE: 405–700 nm); outside the measured range each end value
 * is held constant, the usual treatment of truncated spectral data in colorimetry (CIE 15:2004,
 * §7.2.2: missing values at the ends are replaced by the nearest measured value) rather than
 * zero, which would darken deep reds and violets that the filter in fact passes. Nothing is
 * invented in between: the published points already sit on the 5 nm grid.
 */
export function transmissionOnCmfGrid(filter: Pick<ColourFilter, 'startNm' | 'transmission'>): number[] {
  const first = (filter.startNm - CIE1931_START_NM) / CIE1931_STEP_NM;
  const t = filter.transmission;
  return CIE1931_2DEG.map((_, i) => t[Math.min(t.length - 1, Math.max(0, i - first))]);
}
