import { describe, expect, it } from 'vitest';
import { cctAndDuv } from '../../../src/core/colour/cctDuv';
import { filterSpectrum } from '../../../src/core/colour/colourFilterSpectra';
import { filteredColour, xyzToLinearSrgb } from '../../../src/core/colour/filteredColour';
import { moduleColour } from '../../../src/core/colour/moduleColour';
import { cctToLinearRgb } from '../../../src/core/photometry/cct';

const luminance = ([r, g, b]: readonly number[]): number => 0.2126 * r + 0.7152 * g + 0.0722 * b;

describe('filtered colour (CIE 15:2004 colorimetry)', () => {
  it('Planck at 2856 K gives CIE illuminant A (x 0.44757, y 0.40745) within 0.0005', () => {
    const c = filteredColour(2856, null);
    expect(Math.abs(c.x - 0.44757)).toBeLessThan(0.0005);
    expect(Math.abs(c.y - 0.40745)).toBeLessThan(0.0005);
    // The spectral path (a filter passing everything) agrees with the closed path.
    const clear = filteredColour(2856, Array(81).fill(1));
    expect(Math.abs(clear.x - 0.44757)).toBeLessThan(0.0005);
    expect(Math.abs(clear.y - 0.40745)).toBeLessThan(0.0005);
  });

  it("unfiltered is exactly today's cctToLinearRgb; a clear (τ = 1) filter matches it to 1e-12", () => {
    for (const k of [1800, 2700, 3000, 4000, 6500, 12000]) {
      expect(moduleColour(k, undefined).linearRgb).toEqual(cctToLinearRgb(k));
      const clear = filteredColour(k, Array(81).fill(1));
      clear.linearRgb.forEach((v, i) => expect(v).toBeCloseTo(cctToLinearRgb(k)[i], 12));
      expect(clear.transmission).toBeCloseTo(1, 12);
    }
  });

  it('a flat grey τ = 0.4 keeps the chromaticity and scales the luminance to 0.4', () => {
    const c = filteredColour(3000, Array(81).fill(0.4));
    const ref = filteredColour(3000, null);
    expect(c.transmission).toBeCloseTo(0.4, 12);
    expect(c.x).toBeCloseTo(ref.x, 12);
    expect(luminance(c.linearRgb)).toBeCloseTo(0.4, 12);
    c.linearRgb.forEach((v, i) => expect(v).toBeCloseTo(0.4 * ref.linearRgb[i], 12));
  });

  it("the baker's colour carries the lumen loss: luminance of the linear RGB = τ_v for every library gel at 3000 K", () => {
    for (const id of ['lee-204', 'lee-201', 'lee-209', 'lee-106', 'lee-119', 'lee-139']) {
      const c = moduleColour(3000, id);
      expect(luminance(c.linearRgb)).toBeCloseTo(c.transmission, 12);
      for (const v of c.linearRgb) expect(v).toBeGreaterThanOrEqual(0);
    }
  });

  it('full CTB (LEE 201) on 3200 K: measured 5689 K, Duv +0.0009 — LEE states it converts 3200 K to 5700 K', () => {
    // The issue expected 5500–5600 K. LEE's own sheet says "3200 K to 5700 K", and its stated
    // chromaticity under the tungsten source (x 0.3300, y 0.3390, copied in colourFilterLibrary.test.ts)
    // is CCT 5610 K; the 0.0017 difference in x is the published curve stopping at 405/700 nm.
    const c = moduleColour(3200, 'lee-201');
    expect(c.white).not.toBeNull();
    expect(c.white!.cct).toBeGreaterThan(5650);
    expect(c.white!.cct).toBeLessThan(5730);
    expect(Math.abs(c.white!.duv)).toBeLessThan(0.002);
    const stated = cctAndDuv(0.33, 0.339)!;
    expect(Math.abs(stated.cct - c.white!.cct)).toBeLessThan(120);
  });

  it("CTO/CTB under 3200 K land on LEE's stated tungsten chromaticities within 0.003 (their stated tungsten source fits 3200 K)", () => {
    for (const id of ['lee-204', 'lee-205', 'lee-206', 'lee-285', 'lee-201', 'lee-202', 'lee-203', 'lee-281', 'lee-106']) {
      const c = moduleColour(3200, id);
      const s = filterSpectrum(id).stated.sourceA!;
      expect(Math.abs(c.x - s.x)).toBeLessThan(0.003);
      expect(Math.abs(c.y - s.y)).toBeLessThan(0.003);
    }
  });

  it("neutral densities 0.3/0.6/0.9 pass LEE's stated tungsten Y (50.0/24.5/11.8 %) within 0.007, and ≈ 10^−D within 0.012", () => {
    const cases: [string, number][] = [
      ['lee-209', 0.3],
      ['lee-210', 0.6],
      ['lee-211', 0.9],
    ];
    for (const [id, density] of cases) {
      const tau = moduleColour(3200, id).transmission;
      expect(Math.abs(tau - filterSpectrum(id).stated.sourceA!.Y / 100)).toBeLessThan(0.007);
      expect(Math.abs(tau - 10 ** -density)).toBeLessThan(0.012); // measured at 3200 K: 0.0021 / 0.0113 / 0.0011
    }
  });

  it('xyzToLinearSrgb: D65 white → [1, 1, 1] within 0.2 %, black → black, out-of-gamut clamped at luminance Y', () => {
    const d65 = xyzToLinearSrgb([0.95047, 1, 1.08883]);
    for (const v of d65) expect(Math.abs(v - 1)).toBeLessThan(0.002);
    expect(xyzToLinearSrgb([0, 0, 0])).toEqual([0, 0, 0]);
    const deepBlue = moduleColour(3000, 'lee-119'); // LEE 119 Dark Blue: outside sRGB (red < 0 before clamping)
    expect(deepBlue.linearRgb[0]).toBe(0);
    expect(luminance(deepBlue.linearRgb)).toBeCloseTo(deepBlue.transmission, 12);
  });
});
