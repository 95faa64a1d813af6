/**
 * The colour-filter library's spectral transmission curves, as published by the manufacturers
 * (src/core/colour/colour-filter-spectra.json, written with the index by
 * scripts/extractColourFilters.mjs). They are loaded on first need, not with the planner's first
 * screen (docs/colour-filters.md, "Two files"): `loadColourFilterSpectra()` once, then the
 * synchronous accessors below. Hosts load them where a colour may be computed (the CLI at start,
 * the browser when a configuration uses a filter, when the filter picker opens, before a bake);
 * a colour asked for before that is a `ColourFilterSpectraPending` error, never a wrong colour.
 * The schema and the data are one lazy chunk (./parseColourFilterSpectra.ts and the JSON).
 */
import { InputError } from '../inputError';
import { CIE1931_2DEG, CIE1931_START_NM, CIE1931_STEP_NM } from '../photometry/cieCmf1931';
import type { ColourFilterSpectra, FilterSpectrum } from './parseColourFilterSpectra';

export type { ColourFilterSpectra, FilterSpectrum };

/** A filter's colour was asked for before the spectra were loaded (await loadColourFilterSpectra()). */
export class ColourFilterSpectraPending extends Error {
  override readonly name = 'ColourFilterSpectraPending';
  constructor(id: string) {
    super(`the colour-filter spectra are not loaded yet (filter '${id}'): await loadColourFilterSpectra() first`);
  }
}

let loaded: ColourFilterSpectra | undefined;
let byId = new Map<string, FilterSpectrum>();
let loading: Promise<ColourFilterSpectra> | undefined;
const listeners = new Set<() => void>();

/** Loads (once; later calls share the promise) and returns the spectra. */
export function loadColourFilterSpectra(): Promise<ColourFilterSpectra> {
  if (loaded) return Promise.resolve(loaded);
  loading ??= Promise.all([import('./parseColourFilterSpectra'), import('./colour-filter-spectra.json')]).then(
    ([parser, json]) => {
      const data = parser.parseColourFilterSpectra(json.default);
      loaded = data;
      byId = new Map(data.spectra.map((s) => [s.id, s]));
      for (const l of [...listeners]) l();
      return data;
    },
    (error: unknown) => {
      loading = undefined; // a failed fetch (offline for a moment) may be retried
      throw error;
    },
  );
  return loading;
}

/** Whether the spectra are loaded (the accessors below then answer synchronously). */
export function colourFilterSpectraLoaded(): boolean {
  return loaded !== undefined;
}

/** Calls `listener` once the spectra have loaded; returns the unsubscribe function. */
export function onColourFilterSpectraLoaded(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/** The loaded spectra with the dataset's provenance (the CLI prints it). */
export function colourFilterSpectra(): ColourFilterSpectra {
  if (!loaded) throw new ColourFilterSpectraPending('*');
  return loaded;
}

/** The curve of library filter `id`: InputError for an unknown id, ColourFilterSpectraPending before loading. */
export function filterSpectrum(id: string): FilterSpectrum {
  const s = byId.get(id);
  if (s) return s;
  if (!loaded) throw new ColourFilterSpectraPending(id);
  throw new InputError(`unknown colour filter '${id}' (not in the filter library)`);
}

/**
 * τ(λ) on the colour-matching functions' grid, 380–780 nm in 5 nm steps (81 values). The published
 * curves stop short of the CMF range (LEE: 405–700 nm); outside the measured range each end value
 * is held constant, the usual treatment of truncated spectral data in colorimetry (CIE 15:2004,
 * §7.2.2: missing values at the ends are replaced by the nearest measured value) rather than
 * zero, which would darken deep reds and violets that the filter in fact passes. Nothing is
 * invented in between: the published points already sit on the 5 nm grid.
 */
export function transmissionOnCmfGrid(filter: Pick<FilterSpectrum, 'startNm' | 'transmission'>): number[] {
  const first = (filter.startNm - CIE1931_START_NM) / CIE1931_STEP_NM;
  const t = filter.transmission;
  return CIE1931_2DEG.map((_, i) => t[Math.min(t.length - 1, Math.max(0, i - first))]);
}
