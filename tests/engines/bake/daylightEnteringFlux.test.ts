import { describe, expect, it } from 'vitest';
import { GLAZING_PRESETS, OPEN_OPENING, diffuseTransmittance, glazingTransmittance, type Glazing } from '../../../src/core/daylight/glazing';
import { cieOvercastSky, uniformSky } from '../../../src/core/daylight/skies';
import type { BakeDaylight } from '../../../src/engines/bake/daylight/bakeDaylight';
import { daylightEnteringFlux } from '../../../src/engines/bake/daylight/daylightEnteringFlux';
import type { BakeWindow } from '../../../src/engines/bake/daylight/daylightWindows';

/** A 1.5 × 1.2 m window in a south wall (outward +z), its glass given. */
function southWindow(glazing: Glazing): BakeWindow {
  return { opening: 0, corner: [1, 0.9, 4], edgeA: [1.5, 0, 0], edgeB: [0, 1.2, 0], inward: [0, 0, -1], area: 1.8, glazing };
}

const daylight = (d: Partial<BakeDaylight>): BakeDaylight => ({ sky: null, sun: null, groundLuminance: 0, glazing: new Map(), ...d });

describe('daylight entering through the windows (the adopted white weighs daylight by it)', () => {
  it('a uniform sky through an open vertical window: E_v = L·π/2 = E_h/2, plus L_g·π/2 from the ground (0.3 %)', () => {
    const w = southWindow(OPEN_OPENING);
    const sky = daylightEnteringFlux(daylight({ sky: uniformSky(10_000) }), [w]);
    expect(Math.abs(sky / (1.8 * 5_000) - 1)).toBeLessThan(0.003);
    const both = daylightEnteringFlux(daylight({ sky: uniformSky(10_000), groundLuminance: 600 }), [w]);
    expect(Math.abs((both - sky) / (1.8 * 600 * (Math.PI / 2)) - 1)).toBeLessThan(0.003);
  });

  it('double glazing under a uniform sky: the hemispherical-diffuse transmittance τ_d (0.5 %)', () => {
    const g: Glazing = { ...GLAZING_PRESETS.double, frameFraction: 0 };
    const flux = daylightEnteringFlux(daylight({ sky: uniformSky(10_000), groundLuminance: 10_000 / Math.PI }), [southWindow(g)]);
    // Sky above and ground below at one luminance L: E = τ_d·π·L over the whole hemisphere.
    expect(Math.abs(flux / (1.8 * diffuseTransmittance(g) * 10_000) - 1)).toBeLessThan(0.005);
  });

  it("the sun's beam: E_n·cos θ·τ(θ) when it faces the window, nothing from behind or below the horizon (exact)", () => {
    const g: Glazing = { ...GLAZING_PRESETS.single, frameFraction: 0 };
    const dir: [number, number, number] = [0, Math.sin(0.5), Math.cos(0.5)];
    const flux = daylightEnteringFlux(daylight({ sun: { direction: dir, normalIlluminance: 80_000 } }), [southWindow(g)]);
    expect(flux).toBeCloseTo(1.8 * 80_000 * Math.cos(0.5) * glazingTransmittance(g, Math.cos(0.5)), 6);
    expect(daylightEnteringFlux(daylight({ sun: { direction: [0, 0.5, -Math.sqrt(0.75)], normalIlluminance: 80_000 } }), [southWindow(g)])).toBe(0);
    expect(daylightEnteringFlux(daylight({ sun: { direction: [0, -0.1, Math.sqrt(0.99)], normalIlluminance: 80_000 } }), [southWindow(g)])).toBe(0);
  });

  it('CIE overcast sky: a vertical window gets 0.396 of the horizontal illuminance (Lz(1+2 sinθ)/3 integrated: 3/7·(…)) within 0.5 %', () => {
    // E_v/E_h for the CIE overcast sky on an unobstructed vertical plane, sky only: with L = Lz(1+2u)/3
    // (u = sin elevation) and E_h = 7π·Lz/9, E_v = Lz/3·(π/2 + 2·(2/3)) (∫ cos-weighted over the half
    // hemisphere in front: ∫L·cosα dω with ∫ dω cosα = π/2 and ∫ u cosα dω = 2/3).
    const lz = 1;
    const ev = (lz / 3) * (Math.PI / 2 + 4 / 3);
    const eh = (7 * Math.PI * lz) / 9;
    const flux = daylightEnteringFlux(daylight({ sky: cieOvercastSky(10_000) }), [southWindow(OPEN_OPENING)]);
    expect(Math.abs(flux / (1.8 * 10_000 * (ev / eh)) - 1)).toBeLessThan(0.005);
  });

  it('no sky, no sun, a dark ground or no window: 0, never NaN', () => {
    expect(daylightEnteringFlux(daylight({}), [southWindow(OPEN_OPENING)])).toBe(0);
    expect(daylightEnteringFlux(daylight({ sky: uniformSky(10_000) }), [])).toBe(0);
  });
});
