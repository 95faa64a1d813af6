import { describe, expect, it, vi } from 'vitest';
import { COLOUR_FILTER_LIBRARY, findColourFilter, parseColourFilterLibrary } from '../../../src/core/colour/colourFilterLibrary';
import { moduleColour as moduleColourTop } from '../../../src/core/colour/moduleColour';
import { colourFilterSpectra, filterSpectrum, transmissionOnCmfGrid } from '../../../src/core/colour/colourFilterSpectra';
import { parseColourFilterSpectra } from '../../../src/core/colour/parseColourFilterSpectra';

/**
 * Spot values copied by hand from lighting_filters 0.1.1 (PyPI), dataset/filters.json
 * (sha256 a0a62eb1…1b790b54), keys L201, L209, L106, L204, field `sd` (strings in the file) and
 * `src_a` (x, y, Y %): the published LEE curves the library must carry unchanged.
 */
const DATASET: Record<string, { sd: Record<number, number>; srcA: { x: number; y: number; Y: number } }> = {
  'lee-201': { sd: { 405: 0.62901, 450: 0.77132, 550: 0.27973, 650: 0.2568, 700: 0.43912 }, srcA: { x: 0.33, y: 0.339, Y: 35 } },
  'lee-209': { sd: { 405: 0.47185, 450: 0.50162, 550: 0.50664, 650: 0.52231, 700: 0.69553 }, srcA: { x: 0.423, y: 0.404, Y: 50 } },
  'lee-106': { sd: { 405: 0.00287, 450: 0.00183, 550: 0.00031, 650: 0.7312, 700: 0.81051 }, srcA: { x: 0.693, y: 0.305, Y: 12.8 } },
  'lee-204': { sd: { 405: 0.16015, 450: 0.17923, 550: 0.52531, 650: 0.87178, 700: 0.92403 }, srcA: { x: 0.51, y: 0.42, Y: 62.8 } },
};

describe('colour filter library', () => {
  it('holds at least 30 filters with spectra: CTO and CTB in five strengths, ND 0.15–0.9, and colours', () => {
    const f = COLOUR_FILTER_LIBRARY.filters;
    expect(f.length).toBeGreaterThanOrEqual(30);
    const ids = (kind: string) => f.filter((x) => x.kind === kind).map((x) => x.number);
    expect(ids('cto')).toEqual(['204', '285', '205', '206', '223']);
    expect(ids('ctb')).toEqual(['201', '281', '202', '203', '218']);
    expect(ids('nd')).toEqual(['298', '209', '210', '211']);
    expect(ids('colour').length).toBeGreaterThanOrEqual(20);
    expect(colourFilterSpectra().spectra.map((s) => s.id)).toEqual(f.map((x) => x.id)); // one curve each, same order
    for (const x of f) {
      const s = filterSpectrum(x.id);
      expect(s.startNm).toBe(405);
      expect(s.transmission).toHaveLength(60); // 405–700 nm at 5 nm, as published
      expect(s.datasetKey).toBe(`L${x.number}`);
    }
  });

  it('carries the published values unchanged (spot checks against the dataset)', () => {
    for (const [id, ref] of Object.entries(DATASET)) {
      const f = filterSpectrum(id);
      for (const [nm, t] of Object.entries(ref.sd)) expect(f.transmission[(Number(nm) - 405) / 5]).toBe(t);
      expect(f.stated.sourceA).toEqual(ref.srcA);
    }
  });

  it('on the 380–780 nm CMF grid: measured points in place, end values held outside 405–700 nm', () => {
    const grid = transmissionOnCmfGrid(filterSpectrum('lee-106'));
    expect(grid).toHaveLength(81);
    expect(grid[(550 - 380) / 5]).toBe(0.00031);
    expect(grid[(650 - 380) / 5]).toBe(0.7312);
    expect(grid.slice(0, 6)).toEqual(Array(6).fill(0.00287)); // 380–405 nm
    expect(grid.slice((700 - 380) / 5)).toEqual(Array(17).fill(0.81051)); // 700–780 nm
  });

  it('refuses a broken index naming the field, and unknown ids', () => {
    const bad = structuredClone(COLOUR_FILTER_LIBRARY) as { filters: { kind: string; id: string }[] };
    bad.filters[2].kind = 'purple';
    expect(() => parseColourFilterLibrary(bad)).toThrow(/colour-filters\.json: filters\.2\.kind/);
    const dup = structuredClone(COLOUR_FILTER_LIBRARY);
    dup.filters[1].id = dup.filters[0].id;
    expect(() => parseColourFilterLibrary(dup)).toThrow(/duplicate filter id 'lee-204'/);
    expect(() => findColourFilter('lee-999')).toThrow(/unknown colour filter 'lee-999'/);
    expect(() => filterSpectrum('lee-999')).toThrow(/unknown colour filter 'lee-999'/);
  });

  it('refuses broken spectra naming the filter and field, and curves that do not match the index', () => {
    const good = colourFilterSpectra();
    const bad = structuredClone(good);
    bad.spectra[2].transmission[4] = 1.5;
    expect(() => parseColourFilterSpectra(bad)).toThrow(/colour-filter-spectra\.json: spectra\.2\.transmission\.4/);
    const late = structuredClone(good);
    late.spectra[0].startNm = 730;
    expect(() => parseColourFilterSpectra(late)).toThrow(/reaches 1025 nm, past 780 nm/);
    const dup = structuredClone(good);
    dup.spectra[1].id = dup.spectra[0].id;
    expect(() => parseColourFilterSpectra(dup)).toThrow(/duplicate filter id 'lee-204'/);
    const missing = structuredClone(good);
    missing.spectra.splice(3, 1);
    expect(() => parseColourFilterSpectra(missing)).toThrow(new RegExp(`no curve for filter '${good.spectra[3].id}'`));
    const extra = structuredClone(good);
    extra.spectra.push({ ...extra.spectra[0], id: 'lee-999' });
    expect(() => parseColourFilterSpectra(extra)).toThrow(/curve for 'lee-999', which colour-filters\.json does not list/);
  });

  it('before loading: ids are known at once, a colour through a filter is a pending error, loading once notifies', async () => {
    vi.resetModules();
    const spectra = await import('../../../src/core/colour/colourFilterSpectra');
    const { moduleColour, needsColourFilterSpectra } = await import('../../../src/core/colour/moduleColour');
    const library = await import('../../../src/core/colour/colourFilterLibrary');
    expect(spectra.colourFilterSpectraLoaded()).toBe(false);
    expect(library.colourFilter('lee-204')?.name).toBe('Full C.T. Orange');
    expect(needsColourFilterSpectra([undefined, 'lee-204'])).toBe(true);
    expect(needsColourFilterSpectra([undefined])).toBe(false);
    expect(moduleColour(3000, undefined).transmission).toBe(1); // no filter: no spectra needed
    expect(() => moduleColour(3000, 'lee-204')).toThrow(spectra.ColourFilterSpectraPending);
    expect(() => moduleColour(3000, 'lee-204')).toThrow(/not loaded yet \(filter 'lee-204'\)/);
    let calls = 0;
    spectra.onColourFilterSpectraLoaded(() => calls++);
    const [a, b] = await Promise.all([spectra.loadColourFilterSpectra(), spectra.loadColourFilterSpectra()]);
    expect(a).toBe(b);
    expect(calls).toBe(1);
    expect(needsColourFilterSpectra(['lee-204'])).toBe(false);
    expect(moduleColour(3000, 'lee-204').transmission).toBeCloseTo(moduleColourLoaded(3000, 'lee-204'), 12);
  });
});

// The module instance loaded by the setup file (tests/setup/colourFilterSpectra.ts), for comparison.
function moduleColourLoaded(cct: number, id: string): number {
  return moduleColourTop(cct, id).transmission;
}
