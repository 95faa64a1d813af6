import { describe, expect, it } from 'vitest';
import { COLOUR_FILTER_LIBRARY, findColourFilter, parseColourFilterLibrary, transmissionOnCmfGrid } from '../../../src/core/colour/colourFilterLibrary';

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
    for (const x of f) {
      expect(x.startNm).toBe(405);
      expect(x.transmission).toHaveLength(60); // 405–700 nm at 5 nm, as published
      expect(x.datasetKey).toBe(`L${x.number}`);
    }
  });

  it('carries the published values unchanged (spot checks against the dataset)', () => {
    for (const [id, ref] of Object.entries(DATASET)) {
      const f = findColourFilter(id);
      for (const [nm, t] of Object.entries(ref.sd)) expect(f.transmission[(Number(nm) - 405) / 5]).toBe(t);
      expect(f.stated.sourceA).toEqual(ref.srcA);
    }
  });

  it('on the 380–780 nm CMF grid: measured points in place, end values held outside 405–700 nm', () => {
    const f = findColourFilter('lee-106');
    const grid = transmissionOnCmfGrid(f);
    expect(grid).toHaveLength(81);
    expect(grid[(550 - 380) / 5]).toBe(0.00031);
    expect(grid[(650 - 380) / 5]).toBe(0.7312);
    expect(grid.slice(0, 6)).toEqual(Array(6).fill(0.00287)); // 380–405 nm
    expect(grid.slice((700 - 380) / 5)).toEqual(Array(17).fill(0.81051)); // 700–780 nm
  });

  it('refuses broken data naming the field, and unknown ids', () => {
    const good = structuredClone(COLOUR_FILTER_LIBRARY);
    const bad = structuredClone(good);
    bad.filters[2].transmission[4] = 1.5;
    expect(() => parseColourFilterLibrary(bad)).toThrow(/filters\.2\.transmission\.4/);
    const dup = structuredClone(good);
    dup.filters[1].id = dup.filters[0].id;
    expect(() => parseColourFilterLibrary(dup)).toThrow(/duplicate filter id 'lee-204'/);
    const late = structuredClone(good);
    late.filters[0].startNm = 730;
    expect(() => parseColourFilterLibrary(late)).toThrow(/reaches 1025 nm, past 780 nm/);
    expect(() => findColourFilter('lee-999')).toThrow(/unknown colour filter 'lee-999'/);
  });
});
