import { describe, expect, it } from 'vitest';
import { cctToLinearRgb, ColorTemperatureError, planckianXyz } from '../../../src/core/photometry';
import { CIE1931_2DEG } from '../../../src/core/photometry/cieCmf1931';

const luminance = ([r, g, b]: number[]): number => 0.2126 * r + 0.7152 * g + 0.0722 * b;

describe('CCT → linear sRGB', () => {
  it('the embedded CIE 1931 table is the 2° observer (81 rows; Σx̄ = Σȳ = Σz̄ within 0.1 %)', () => {
    expect(CIE1931_2DEG.length).toBe(81);
    const sums = [0, 1, 2].map((k) => CIE1931_2DEG.reduce((s, row) => s + row[k], 0));
    // Equal-energy white has x = y = 1/3, i.e. equal integrals (CIE 15:2004).
    expect(Math.abs(sums[0] / sums[1] - 1)).toBeLessThan(1e-3);
    expect(Math.abs(sums[2] / sums[1] - 1)).toBeLessThan(1e-3);
    expect(CIE1931_2DEG[35][1]).toBe(1); // ȳ(555 nm) = 1
  });

  it('Planckian chromaticities match published values (CIE 15:2004 / Wyszecki & Stiles)', () => {
    // Illuminant A (2856 K): x = 0.44757, y = 0.40745.
    const [X, Y, Z] = planckianXyz(2856);
    expect(X / (X + Y + Z)).toBeCloseTo(0.4476, 3);
    expect(Y / (X + Y + Z)).toBeCloseTo(0.4074, 3);
    // 6500 K on the locus: x ≈ 0.3135, y ≈ 0.3236.
    const [x6, y6, z6] = planckianXyz(6500);
    expect(x6 / (x6 + y6 + z6)).toBeCloseTo(0.3135, 3);
    expect(y6 / (x6 + y6 + z6)).toBeCloseTo(0.3236, 3);
  });

  it('6504 K is close to the D65 white [1, 1, 1] (within 5 %)', () => {
    for (const v of cctToLinearRgb(6504)) expect(Math.abs(v - 1)).toBeLessThan(0.05);
  });

  it('has unit luminance and no negative component over 1000–20000 K', () => {
    for (let k = 1000; k <= 20000; k += 250) {
      const rgb = cctToLinearRgb(k);
      expect(luminance(rgb)).toBeCloseTo(1, 12);
      for (const v of rgb) expect(v).toBeGreaterThanOrEqual(0);
    }
  });

  it('2700 K is reddish and blue/red rises monotonically with temperature', () => {
    const [r, g, b] = cctToLinearRgb(2700);
    expect(r).toBeGreaterThan(g);
    expect(g).toBeGreaterThan(b);
    let previous = -1;
    for (let k = 1000; k <= 20000; k += 100) {
      const [rr, , bb] = cctToLinearRgb(k);
      const ratio = bb / rr;
      expect(ratio).toBeGreaterThanOrEqual(previous);
      previous = ratio;
    }
    expect(cctToLinearRgb(1000)[2]).toBe(0); // out of gamut: clamped
  });

  it('rejects temperatures outside 1000–20000 K with an InputError', () => {
    for (const k of [999, 20001, Number.NaN, Infinity]) expect(() => cctToLinearRgb(k)).toThrow(ColorTemperatureError);
  });
});
