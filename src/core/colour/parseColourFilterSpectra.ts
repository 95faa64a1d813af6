/**
 * The schema of src/core/colour/colour-filter-spectra.json (docs/colour-filters.md, "Two files"):
 * validated when loaded, so a broken file fails naming the filter and field, and checked against
 * the index (colour-filters.json): one curve per library filter, no other. Loaded with the data by
 * loadColourFilterSpectra() (./colourFilterSpectra.ts), outside the planner's first screen.
 */
import { z } from 'zod/mini';
import { InputError } from '../inputError';
import { CIE1931_2DEG, CIE1931_START_NM, CIE1931_STEP_NM } from '../photometry/cieCmf1931';
import { COLOUR_FILTER_LIBRARY, FILTER_ID_PATTERN, parseFilterFile } from './colourFilterLibrary';

const LAST_NM = CIE1931_START_NM + CIE1931_STEP_NM * (CIE1931_2DEG.length - 1);

const statedSchema = z.strictObject({ x: z.number().check(z.gte(0), z.lte(1)), y: z.number().check(z.gte(0), z.lte(1)), Y: z.number().check(z.gte(0), z.lte(100)) });

const spectrumSchema = z
  .strictObject({
    id: z.string().check(z.regex(FILTER_ID_PATTERN)),
    /** First wavelength of `transmission`, nm; on the CMF grid (380 + 5k). */
    startNm: z.number().check(z.int()),
    stepNm: z.literal(5),
    /** Spectral transmittance τ(λ), 0..1, from startNm in 5 nm steps, as published. */
    transmission: z.array(z.number().check(z.gte(0), z.lte(1))).check(z.minLength(2)),
    /** CIE x, y, Y (Y in per cent) the dataset states under its source A and source C. */
    stated: z.strictObject({ sourceA: z.optional(statedSchema), sourceC: z.optional(statedSchema) }),
    source: z.string().check(z.url()),
    datasetKey: z.string().check(z.minLength(1)),
  })
  .check(
    z.superRefine((f, ctx) => {
      const end = f.startNm + f.stepNm * (f.transmission.length - 1);
      if ((f.startNm - CIE1931_START_NM) % CIE1931_STEP_NM !== 0 || f.startNm < CIE1931_START_NM) ctx.addIssue({ code: 'custom', path: ['startNm'], message: 'must lie on the 380–780 nm, 5 nm grid' });
      if (end > LAST_NM) ctx.addIssue({ code: 'custom', path: ['transmission'], message: `reaches ${end} nm, past ${LAST_NM} nm` });
    }),
  );

const spectraSchema = z.strictObject({
  formatVersion: z.literal(1),
  dataset: z.strictObject({ name: z.string(), url: z.string().check(z.url()), licence: z.string(), sha256: z.string().check(z.regex(/^[0-9a-f]{64}$/)) }),
  spectra: z.array(spectrumSchema).check(z.minLength(1)),
});

export type FilterSpectrum = z.infer<typeof spectrumSchema>;
export type ColourFilterSpectra = z.infer<typeof spectraSchema>;

/**
 * Parses spectra data (the JSON file, or a test's) and checks it against the index: one curve per
 * library filter, no other. Throws InputError naming the filter and field.
 */
export function parseColourFilterSpectra(data: unknown): ColourFilterSpectra {
  const parsed = parseFilterFile('colour-filter-spectra.json', spectraSchema, data, (file) => file.spectra);
  const listed = new Set(COLOUR_FILTER_LIBRARY.filters.map((f) => f.id));
  for (const id of listed) {
    if (!parsed.spectra.some((s) => s.id === id)) throw new InputError(`colour-filter-spectra.json: no curve for filter '${id}' of colour-filters.json`);
  }
  const extra = parsed.spectra.find((s) => !listed.has(s.id));
  if (extra) throw new InputError(`colour-filter-spectra.json: curve for '${extra.id}', which colour-filters.json does not list`);
  return parsed;
}
