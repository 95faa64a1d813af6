import { describe, expect, it } from 'vitest';
import { daylightAvailability, SOLAR_ILLUMINANCE_CONSTANT } from '../../../src/core/daylight/daylightAvailability';
import { CIE_GENERAL_SKY_TYPES, cieGeneralSky, cieOvercastSky, generalSkyIrradianceIntegral, generalSkyRelativeLuminance, groundLuminance, hemisphereCosineIntegral, uniformSky, type Direction } from '../../../src/core/daylight/skies';
import { sunDirection } from '../../../src/core/daylight/solarPosition';

/** Composite Simpson on [a, b]: an integrator independent of the sky module's Gauss rule. */
function simpson(f: (x: number) => number, a: number, b: number, n = 20000): number {
  let s = f(a) + f(b);
  for (let i = 1; i < n; i++) s += (i % 2 ? 4 : 2) * f(a + ((b - a) * i) / n);
  return (s * (b - a)) / (3 * n);
}

/** ∫ f cos Z dω by the plain midpoint rule on an elevation × azimuth grid (dω = cos α dα dφ). */
function midpointHemisphere(f: (d: Direction) => number, nAlt = 300, nAz = 600): number {
  let sum = 0;
  for (let i = 0; i < nAlt; i++) {
    const alt = ((i + 0.5) * Math.PI) / 2 / nAlt;
    for (let j = 0; j < nAz; j++) {
      const az = ((j + 0.5) * 2 * Math.PI) / nAz;
      const d: Direction = [Math.cos(alt) * Math.sin(az), Math.sin(alt), -Math.cos(alt) * Math.cos(az)];
      sum += f(d) * Math.sin(alt) * Math.cos(alt);
    }
  }
  return (sum * (Math.PI / 2 / nAlt) * (2 * Math.PI)) / nAz;
}

describe('skies', () => {
  it('normalises the uniform and the CIE overcast sky to the horizontal illuminance (7π L_z / 9)', () => {
    const u = uniformSky(10000);
    expect(u.luminance([0, 1, 0])).toBeCloseTo(10000 / Math.PI, 9);
    expect(u.luminance([1, 0, 0])).toBe(0);
    expect(hemisphereCosineIntegral(u.luminance)).toBeCloseTo(10000, 6);
    const o = cieOvercastSky(10000);
    expect((7 * Math.PI * o.zenithLuminance) / 9).toBeCloseTo(10000, 9);
    // L(θ) = L_z (1 + 2 sin θ) / 3: a third of the zenith's at the horizon.
    expect(o.luminance([Math.SQRT1_2, Math.SQRT1_2, 0]) / o.zenithLuminance).toBeCloseTo((1 + Math.SQRT2) / 3, 12);
    expect(o.luminance([1, 1e-9, 0]) / o.zenithLuminance).toBeCloseTo(1 / 3, 8);
    expect(hemisphereCosineIntegral(o.luminance)).toBeCloseTo(10000, 6);
  });

  it('has the 15 CIE S 011 types, type 5 uniform, type 1 beside the Moon–Spencer overcast sky', () => {
    expect(CIE_GENERAL_SKY_TYPES.map((t) => t.type)).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15]);
    const sun = sunDirection(35, 160);
    for (const d of [sunDirection(10, 0), sunDirection(60, 250), sunDirection(85, 90)]) expect(generalSkyRelativeLuminance(5, d, sun)).toBeCloseTo(1, 12);
    // Type 1 at the horizon: 1 / (1 + 4 e^{−0.7}) = 0.335, the overcast sky's 1/3.
    expect(generalSkyRelativeLuminance(1, [1, 1e-12, 0], sun)).toBeCloseTo(1 / (1 + 4 * Math.exp(-0.7)), 9);
    // Between, type 1 dips up to 15 % below (1 + 2 sin θ)/3 near 5° (its gradation is exponential,
    // not linear in sin θ; CIE S 011 keeps the traditional overcast sky beside it for that reason).
    for (const [alt, ratio] of [
      [5, 0.8566],
      [20, 0.9047],
      [45, 1.0346],
      [90, 1],
    ]) {
      const d = sunDirection(alt, 30);
      const moonSpencer = (1 + 2 * Math.sin((alt * Math.PI) / 180)) / 3;
      expect(generalSkyRelativeLuminance(1, d, sun) / moonSpencer).toBeCloseTo(ratio, 4);
    }
    expect(() => generalSkyRelativeLuminance(16, [0, 1, 0], sun)).toThrow(/type 16 does not exist/);
  });

  it('makes type 12 the CIE 1973 clear sky (Kittler 1967)', () => {
    const sunAlt = 40;
    const s = sunDirection(sunAlt, 180);
    const zs = ((90 - sunAlt) * Math.PI) / 180;
    const kittler = (d: Direction): number => {
      const chi = Math.acos(d[0] * s[0] + d[1] * s[1] + d[2] * s[2]);
      const f = (x: number) => 0.91 + 10 * Math.exp(-3 * x) + 0.45 * Math.cos(x) ** 2;
      return (f(chi) * (1 - Math.exp(-0.32 / d[1]))) / (f(zs) * (1 - Math.exp(-0.32)));
    };
    for (const d of [sunDirection(10, 0), sunDirection(41, 182), sunDirection(60, 250), sunDirection(88, 90), sunDirection(3, 170)]) {
      // 0.91 is 1 − 10 e^{−3π/2} rounded: agreement to 0.1 %.
      expect(Math.abs(generalSkyRelativeLuminance(12, d, s) / kittler(d) - 1)).toBeLessThan(1e-3);
    }
  });

  it('integrates L cos Z of the azimuthally uniform types against a 1-D Simpson integral (1e-7)', () => {
    for (const t of CIE_GENERAL_SKY_TYPES.filter((x) => x.c === 0 && x.e === 0)) {
      const exact = 2 * Math.PI * simpson((u) => (u > 0 ? ((1 + t.a * Math.exp(t.b / u)) / (1 + t.a * Math.exp(t.b))) * u : 0), 0, 1);
      expect(Math.abs(generalSkyIrradianceIntegral(t.type, sunDirection(30, 100)) / exact - 1)).toBeLessThan(1e-7);
    }
  });

  it('integrates every type with the sun anywhere to 2e-4 of a fine midpoint grid, and converges', () => {
    for (const [alt, az] of [
      [60, 180],
      [15, 250],
      [2, 90],
    ]) {
      const sun = sunDirection(alt, az);
      for (const type of [2, 12, 15]) {
        const gauss = generalSkyIrradianceIntegral(type, sun);
        const fine = midpointHemisphere((d) => generalSkyRelativeLuminance(type, d, sun));
        expect(Math.abs(gauss / fine - 1), `type ${type}, sun at ${alt}°`).toBeLessThan(2e-4);
        const finer = hemisphereCosineIntegral((d) => generalSkyRelativeLuminance(type, d, sun), sun, 96);
        expect(Math.abs(gauss / finer - 1)).toBeLessThan(1e-6);
      }
    }
  });

  it('scales a general sky to the given horizontal illuminance', () => {
    const sun = sunDirection(25, 140);
    const sky = cieGeneralSky(12, sun, 15000);
    expect(Math.abs(hemisphereCosineIntegral(sky.luminance, sun, 48) / 15000 - 1)).toBeLessThan(1e-6);
    // Brightest near the sun, darker opposite it at the same elevation.
    expect(sky.luminance(sunDirection(25, 150))).toBeGreaterThan(3 * sky.luminance(sunDirection(25, 320)));
  });

  it('gives the ground ρ (E_sky + E_sun) / π', () => {
    expect(groundLuminance(10000, 30000, 0.2)).toBeCloseTo(8000 / Math.PI, 9);
  });
});

describe('daylight availability (IES 1984)', () => {
  it('computes the sun and sky illuminances from the published constants', () => {
    const a = daylightAvailability(90, 2, 'clear');
    expect(a.extraterrestrial).toBeCloseTo(SOLAR_ILLUMINANCE_CONSTANT * 1.034, 6);
    expect(a.sunNormal).toBeCloseTo(127500 * 1.034 * Math.exp(-0.21), 6);
    expect(a.sunHorizontal).toBeCloseTo(a.sunNormal, 6);
    expect(a.skyHorizontal).toBeCloseTo(16300, 6);
    const o = daylightAvailability(30, 100, 'overcast');
    expect(o.sunNormal).toBe(0);
    expect(o.skyHorizontal).toBeCloseTo(300 + 21000 * 0.5, 6);
    const p = daylightAvailability(30, 185, 'partly-cloudy');
    expect(p.extraterrestrial).toBeCloseTo(127500 * (1 + 0.034 * Math.cos((2 * Math.PI * 183) / 365)), 6);
    expect(p.sunHorizontal).toBeCloseTo(p.extraterrestrial * Math.exp(-0.8 / 0.5) * 0.5, 6);
    expect(daylightAvailability(-3, 100, 'clear')).toMatchObject({ sunNormal: 0, skyHorizontal: 0 });
  });
});
