import { describe, expect, it } from 'vitest';
import { cctAndDuv, xyToUv } from '../../../src/core/colour/cctDuv';
import { planckianXyz } from '../../../src/core/photometry/cct';

describe('CCT and Duv (CIE 15:2004 §9.5, Ohno 2014)', () => {
  it('points on the locus return their own temperature and Duv 0', () => {
    for (const k of [1200, 2700, 3000, 4000, 5000, 6500, 10000, 18000]) {
      const [X, Y, Z] = planckianXyz(k);
      const r = cctAndDuv(X / (X + Y + Z), Y / (X + Y + Z))!;
      expect(Math.abs(r.cct - k) / k).toBeLessThan(1e-5);
      expect(Math.abs(r.duv)).toBeLessThan(1e-7);
    }
  });

  it('CIE daylight illuminants: D65 (0.31271, 0.32902) 6504 K Duv +0.0032; D50 (0.34567, 0.35850) 5003 K Duv +0.0033', () => {
    // CIE 15:2004 Table T.3 chromaticities; CCTs as CIE gives them (c2 = 1.4388e-2 m·K); Duv from Ohno 2014, table 1.
    const d65 = cctAndDuv(0.31271, 0.32902)!;
    expect(Math.abs(d65.cct - 6504)).toBeLessThan(5);
    expect(Math.abs(d65.duv - 0.0032)).toBeLessThan(0.0002);
    const d50 = cctAndDuv(0.34567, 0.3585)!;
    expect(Math.abs(d50.cct - 5003)).toBeLessThan(5);
    expect(Math.abs(d50.duv - 0.0033)).toBeLessThan(0.0002);
  });

  it('a point moved 0.01 off the locus along the normal has Duv ±0.01 and the same CCT', () => {
    const k = 3500;
    const uv = (t: number) => {
      const [X, Y, Z] = planckianXyz(t);
      return xyToUv(X / (X + Y + Z), Y / (X + Y + Z));
    };
    const [u0, v0] = uv(k);
    const [u1, v1] = uv(k * 1.0001);
    const len = Math.hypot(u1 - u0, v1 - v0);
    // The unit normal pointing toward larger v (above the locus, toward green: Duv > 0).
    const flip = (u1 - u0) / len > 0 ? 1 : -1;
    const n = [(-(v1 - v0) / len) * flip, ((u1 - u0) / len) * flip];
    for (const s of [0.01, -0.01]) {
      const u = u0 + s * n[0];
      const v = v0 + s * n[1];
      // (u, v) → (x, y): x = 3u/(2u − 8v + 4), y = 2v/(2u − 8v + 4) (CIE 15:2004 §8.1 inverted).
      const d = 2 * u - 8 * v + 4;
      const r = cctAndDuv((3 * u) / d, (2 * v) / d)!;
      expect(r.duv).toBeCloseTo(s, 6);
      expect(Math.abs(r.cct - k)).toBeLessThan(1);
    }
  });

  it('no temperature for colours whose nearest locus point is beyond 1000–20000 K, or for NaN', () => {
    expect(cctAndDuv(0.7, 0.29)).toBeNull(); // deep red
    expect(cctAndDuv(0.16, 0.02)).toBeNull(); // deep blue: nearest point past 20000 K
    expect(cctAndDuv(NaN, 0.3)).toBeNull();
  });
});
