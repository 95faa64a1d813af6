/**
 * The flux statistics and the tail of the bounce series as pure functions,
 * without GL (fluxRecord.ts, tailFactor.ts): hand-computed records, the clamp,
 * and the closed grey box, where the explicit bounces plus the tail must give
 * the integrating-sphere illuminance Φ/(S(1−ρ)) for any number of bounces.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { fluxRecord, maxFluxRatio, openRoomRecord, type SurfaceFlux } from '../../../src/engines/bake/fluxRecord';
import { tailFactor } from '../../../src/engines/bake/tailFactor';
import { surfaceLayouts, texelArea } from '../../../src/engines/bake/surfaceLayout';

const close = (a: number, b: number, rel = 1e-12) => expect(Math.abs(a - b)).toBeLessThanOrEqual(rel * Math.max(Math.abs(b), 1e-300));

describe('fluxRecord', () => {
  it('two surfaces by hand: Φ = Σ A·ΣE, r = Σ ρ·A·ΣE / Φ per channel, Φ_Y with the Rec. 709 weights', () => {
    // A: ΣE (10, 20, 30) lx over texels of 0.5 m², ρ (0.2, 0.4, 0.6) → flux (5, 10, 15), reflected (1, 4, 9).
    // B: ΣE (5, 5, 5) over 2 m² texels, ρ 0.8 → flux (10, 10, 10), reflected (8, 8, 8).
    const surfaces: SurfaceFlux[] = [
      { sum: [10, 20, 30], texelArea: 0.5, reflectance: [0.2, 0.4, 0.6] },
      { sum: [5, 5, 5], texelArea: 2, reflectance: [0.8, 0.8, 0.8] },
    ];
    const { ratio, fluxY } = fluxRecord(surfaces, 0.9999);
    // (9, 12, 17) / (15, 20, 25).
    [0.6, 0.6, 0.68].forEach((r, c) => close(ratio[c], r));
    close(fluxY, 0.2126 * 15 + 0.7152 * 20 + 0.0722 * 25);
  });

  it('r is clamped to maxRatio, and a channel without flux has r = 0', () => {
    const { ratio, fluxY } = fluxRecord([{ sum: [4, 4, 0], texelArea: 1, reflectance: [0.9, 0.3, 0.9] }], 0.5);
    expect(ratio).toEqual([0.5, 0.3, 0]);
    close(fluxY, 0.2126 * 4 + 0.7152 * 4);
  });

  it('maxFluxRatio: the largest reflectance, kept below 1 so that r/(1−r) stays finite', () => {
    expect(
      maxFluxRatio([
        [0.2, 0.5, 0.1],
        [0.3, 0.3, 0.3],
      ]),
    ).toBe(0.5);
    expect(maxFluxRatio([[1, 1, 1]])).toBe(0.9999);
  });
});

describe('openRoomRecord (a room with openings, issue 30)', () => {
  it('an integrating sphere with a port: each bounce loses the share f, so r = R_k/R_{k−1} = ρ(1 − f) and the tail gives Φ_in/(S(1 − ρ(1 − f)))', () => {
    // S = 10 m² of ρ 0.9 behind a port taking f = 0.05 of what is reflected; the bounces: E_k = E_0·(ρ(1 − f))^k, uniform.
    const [area, rho, f, e0] = [10, 0.9, 0.05, 100];
    const bounce = (k: number): SurfaceFlux[] => [{ sum: Array(3).fill(e0 * (rho * (1 - f)) ** k) as Rgb, texelArea: area, reflectance: [rho, rho, rho] }];
    const first = openRoomRecord(bounce(0), null, 0.9999);
    [0, 1, 2].forEach((c) => close(first.ratio[c], rho));
    const record = openRoomRecord(bounce(3), bounce(2), 0.9999);
    [0, 1, 2].forEach((c) => close(record.ratio[c], rho * (1 - f)));
    // The flux-weighted reflectance (fluxRecord) would say ρ and overshoot: the tail with it adds ρ/(1−ρ) = 9 E_B instead of 5.9 E_B.
    close(fluxRecord(bounce(3), 0.9999).ratio[1], rho);
    // E_0 + E_1 + E_2 + E_3 + E_3·r/(1−r) is the port formula's mean illuminance E_0/(1 − ρ(1 − f)).
    const sum = [0, 1, 2, 3].reduce((s, k) => s + bounce(k)[0].sum[1], 0) + bounce(3)[0].sum[1] * tailFactor(record.ratio)[1];
    close(sum, e0 / (1 - rho * (1 - f)), 1e-12);
  });

  it('clamps to maxRatio and gives 0 where the bounce before reflected nothing', () => {
    const before: SurfaceFlux[] = [{ sum: [1, 0, 1], texelArea: 1, reflectance: [0.5, 0.5, 0.5] }];
    const now: SurfaceFlux[] = [{ sum: [4, 1, 0.5], texelArea: 1, reflectance: [0.5, 0.5, 0.5] }];
    expect(openRoomRecord(now, before, 0.9).ratio).toEqual([0.9, 0, 0.5]);
  });
});

describe('tailFactor', () => {
  it('is r/(1−r) per channel: the remaining geometric series Σ_{j≥1} r^j', () => {
    const f = tailFactor([0.5, 0.8, 0.99]);
    [1, 4, 99].forEach((v, c) => close(f[c], v));
    expect(tailFactor([0, 0, 0])).toEqual([0, 0, 0]);
  });

  for (const rho of [0.5, 0.9, 0.99]) {
    for (const bounces of [1, 4]) {
      it(`closed grey box ρ = ${rho}, ${bounces} explicit bounce(s): mean of E_0 + … + E_B + E_B·f is Φ/(S(1−ρ))`, () => {
        // 4 × 2.5 × 3 m, S = 59 m²; Φ = 1000 lm of direct light, all on the floor. In a closed grey
        // box bounce k carries ρ^k·Φ (every reflected lumen lands on a surface); spread evenly
        // here, which is the shape the bounces converge to for uniform ρ.
        const room = { width: 4, height: 2.5, depth: 3 };
        const layouts = surfaceLayouts(room, 0.5, 512);
        const area = layouts.reduce((s, l) => s + l.lengthU * l.lengthV, 0);
        expect(area).toBeCloseTo(59, 12);
        const phi = 1000;
        const grey: Rgb = [rho, rho, rho];
        const texels = (i: number) => layouts[i].width * layouts[i].height;
        const record = (lux: (surface: number) => number) =>
          fluxRecord(
            layouts.map((l, i): SurfaceFlux => {
              const e = lux(i) * texels(i);
              return { sum: [e, e, e], texelArea: texelArea(l), reflectance: grey };
            }),
            maxFluxRatio(SURFACE_NAMES.map(() => grey)),
          );
        const floor = layouts[SURFACE_NAMES.indexOf('floor')];
        const records = [record((i) => (i === floor.index ? phi / (floor.lengthU * floor.lengthV) : 0))];
        for (let k = 1; k <= bounces; k++) records.push(record(() => (rho ** k * phi) / area));
        records.forEach((r, k) => {
          close(r.fluxY, rho ** k * phi, 1e-12);
          r.ratio.forEach((x) => close(x, rho));
        });
        const explicit = records.reduce((s, r) => s + r.fluxY / area, 0);
        const tail = (records[bounces].fluxY / area) * tailFactor(records[bounces].ratio)[1];
        close(explicit + tail, phi / (area * (1 - rho)), 1e-12);
      });
    }
  }
});
