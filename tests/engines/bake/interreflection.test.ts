/**
 * Indirect pass. CIE 171:2006 §5.8: a 4 m cube (S = 96 m²) with an isotropic
 * 10 000 lm source at its centre and uniform reflectance ρ has average direct
 * illuminance Φ/S = 104.17 lx and average total Φ/(S(1−ρ)) — exact for any
 * closed box with uniform ρ. And the "grey furnace": with uniform emission in
 * such a box the light is the same everywhere, so each texel must read
 * E0·ρ/(1−ρ) — a per-texel check of the rays, box exits and lookups.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { averageLux, isotropic, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);
const PHI = 10_000;
const S = 96;

function cube(rho: number) {
  return { room: uniformRoom(4, 4, 4, rho), luminaires: [{ photometry: isotropic(PHI / (4 * Math.PI)), position: [2, 2, 2] as [number, number, number], yaw: 0, pitch: 0, roll: 0 }] };
}

describe('CIE 171:2006 §5.8 interreflection, 4 m cube, 10 000 lm isotropic source at the centre', () => {
  const settings = { texelSize: 0.1, samples: 64, bounces: 4 };
  for (const rho of [0.5, 0.8, 0.95]) {
    it(`ρ = ${rho}: average total within 2 % of Φ/(S(1−ρ)) = ${(PHI / (S * (1 - rho))).toFixed(1)} lx`, () => {
      const { maps, report } = baker.bake(cube(rho), settings);
      const expected = PHI / (S * (1 - rho));
      const direct = averageLux(maps, 'direct');
      const total = averageLux(maps, 'total');
      expect(Math.abs(direct - PHI / S) / (PHI / S)).toBeLessThan(0.01);
      expect(Math.abs(total - expected) / expected).toBeLessThan(0.02);
      expect(report.bouncesComputed).toBe(4);
      // Uniform ρ: the flux-weighted reflectance of every bounce is ρ itself.
      report.tailRatio.forEach((r) => expect(r).toBeCloseTo(rho, 6));
    });
  }

  it('ρ = 0.99 (reported): average total within 2 % with the tail estimate, far off without it', () => {
    const expected = PHI / (S * 0.01);
    const withTail = averageLux(baker.bake(cube(0.99), settings).maps, 'total');
    const withoutTail = averageLux(baker.bake(cube(0.99), { ...settings, tail: false }).maps, 'total');
    const error = (withTail - expected) / expected;
    console.info(`CIE 5.8 ρ=0.99: ${withTail.toFixed(1)} lx vs ${expected.toFixed(1)} lx, error ${(100 * error).toFixed(3)} %; without tail ${withoutTail.toFixed(1)} lx`);
    expect(Math.abs(error)).toBeLessThan(0.02);
    // Without the tail, 4 bounces hold only 1 + Σρ^k ≈ 4.9 of the 100 × direct.
    expect(withoutTail / expected).toBeLessThan(0.06);
  });

  it('more bounces without the tail converge toward the same value (ρ = 0.5)', () => {
    const expected = PHI / (S * 0.5);
    const total = averageLux(baker.bake(cube(0.5), { ...settings, bounces: 12, tail: false, samples: 32 }).maps, 'total');
    // Σ_{k≤12} 0.5^k misses 0.5^12 of the series: below 0.03 %.
    expect(Math.abs(total - expected) / expected).toBeLessThan(0.02);
  });
});

describe('grey furnace: uniform emission, uniform ρ, per texel', () => {
  const room = { width: 3, height: 2.5, depth: 4 };
  const settings = { texelSize: 0.125, samples: 16, bounces: 3 };
  const layouts = surfaceLayouts(room, settings.texelSize, resolveBakeSettings().maxTextureSize);
  const emission = (e0: number) => Object.fromEntries(layouts.map((l) => [l.name, new Float32Array(l.width * l.height * 3).fill(e0)])) as Record<SurfaceName, Float32Array>;

  it('grey ρ = 0.7: every texel E0·ρ/(1−ρ) within 0.1 % (tail), and E0·(ρ+ρ²+ρ³) without it', () => {
    const e0 = 100;
    const rho = 0.7;
    for (const tail of [true, false]) {
      const job = baker.startFromDirect({ ...room, reflectance: uniformRoom(1, 1, 1, rho).reflectance }, emission(e0), { ...settings, tail });
      job.run();
      const maps = job.readMaps();
      job.dispose();
      const expected = tail ? (e0 * rho) / (1 - rho) : e0 * (rho + rho ** 2 + rho ** 3);
      for (const name of SURFACE_NAMES) {
        for (const x of maps[name].indirect) expect(Math.abs(x - expected) / expected).toBeLessThan(1e-3);
      }
    }
  });

  it('RGB ρ = (0.3, 0.6, 0.9): each channel ρ/(1−ρ), per texel', () => {
    const rho: [number, number, number] = [0.3, 0.6, 0.9];
    const job = baker.startFromDirect({ ...room, reflectance: uniformRoom(1, 1, 1, rho).reflectance }, emission(1), settings);
    job.run();
    const maps = job.readMaps();
    job.dispose();
    for (const name of SURFACE_NAMES) {
      const m = maps[name].indirect;
      for (let i = 0; i < m.length; i++) {
        const r = rho[i % 3];
        expect(Math.abs(m[i] - r / (1 - r)) / (r / (1 - r))).toBeLessThan(1e-3);
      }
    }
  });
});
