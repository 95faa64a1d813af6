import { describe, expect, it } from 'vitest';
import { loadColourFilterSpectra } from '../../../src/core/colour/colourFilterSpectra';
import { moduleColour } from '../../../src/core/colour/moduleColour';
import { cctToLinearRgb } from '../../../src/core/photometry/cct';
import type { BakeLuminaire } from '../../../src/engines/bake/bakeScene';
import { adoptedWhite, isWhiteLight, sceneAdoptedWhite } from '../../../src/engines/view/adoptedWhite';
import { daylightEnteringFlux } from '../../../src/engines/bake/daylight/daylightEnteringFlux';
import { daylightWindows } from '../../../src/engines/bake/daylight/daylightWindows';
import { loadRenderInputAsync } from '../../../src/hosts/node/renderInput';
import { cat16LinearSrgb, cat16Xyz, degreeOfAdaptation, IDENTITY3, M16, M16_INV } from '../../../src/engines/view/cat16';
import { adaptationFor, adaptingLuminance } from '../../../src/engines/view/chromaticAdaptation';
import { formatAdaptation, parseAdaptation } from '../../../src/engines/view/adaptationSetting';
import { mul3, mulVec3, SRGB_TO_XYZ } from '../../../src/engines/view/colourMatrices';
import { isotropic } from '../../reference/photometryFixtures';

const lum = (c: readonly number[]) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
const lamp = (lumens: number, color: [number, number, number], dimming = 1): BakeLuminaire => ({ photometry: isotropic(lumens), position: [1, 2, 1], yaw: 0, pitch: 0, roll: 0, dimming, color });

describe('CAT16 (Li et al. 2017) and the CAM16 degree of adaptation', () => {
  it('M16 and its inverse multiply to the identity; the degree D at hand-computed luminances; bad L_A gives D(0), never NaN', () => {
    const p = mul3(M16, M16_INV);
    p.forEach((v, i) => expect(v).toBeCloseTo(IDENTITY3[i], 12));
    // D = 1 − (1/3.6)·exp((−L_A − 42)/92): L_A 20 → e^(−62/92) = 0.509709 → 0.858414; L_A 100 → e^(−142/92) = 0.2136367 → 0.9406565.
    expect(degreeOfAdaptation(20)).toBeCloseTo(0.858414, 6);
    expect(degreeOfAdaptation(100)).toBeCloseTo(0.9406565, 6);
    expect(degreeOfAdaptation(Number.NaN)).toBeCloseTo(0.824032, 6);
    expect(degreeOfAdaptation(-5)).toBeCloseTo(0.824032, 6);
    expect(degreeOfAdaptation(Number.POSITIVE_INFINITY)).toBeCloseTo(0.824032, 6);
  });

  it('D = 1 maps the test white to the reference white at its own luminance; D = 0 is the identity; the matrix is affine in D', () => {
    const w = mulVec3(SRGB_TO_XYZ, cctToLinearRgb(2700));
    const d65 = mulVec3(SRGB_TO_XYZ, [1, 1, 1]);
    const full = cat16Xyz(w, d65, 1);
    const mapped = mulVec3(full, w);
    for (let k = 0; k < 3; k++) expect(mapped[k]).toBeCloseTo(d65[k] * (w[1] / d65[1]), 10);
    cat16Xyz(w, d65, 0).forEach((v, i) => expect(v).toBeCloseTo(IDENTITY3[i], 12));
    const half = cat16Xyz(w, d65, 0.4);
    half.forEach((v, i) => expect(v).toBeCloseTo(0.4 * full[i] + 0.6 * IDENTITY3[i], 12));
    // On linear sRGB: 2700 K light becomes neutral grey of the same luminance (to 1e-5: the Y row of the exact
    // inverse of the rounded IEC matrix is 0.2126, 0.7152, 0.0722 only to that).
    const rgb = mulVec3(cat16LinearSrgb(cctToLinearRgb(2700), 1), cctToLinearRgb(2700));
    for (let k = 0; k < 3; k++) expect(rgb[k]).toBeCloseTo(1, 4);
    expect(Math.max(...rgb) - Math.min(...rgb)).toBeLessThan(1e-12);
  });

  it('no NaN: a black, negative or non-finite white gives the identity', () => {
    for (const white of [
      [0, 0, 0],
      [-1, 0.5, 0.2],
      [Number.NaN, 1, 1],
      [1, 0, 0],
    ] as [number, number, number][]) {
      const m = cat16LinearSrgb(white, 1);
      expect(m.every(Number.isFinite)).toBe(true);
    }
    expect(cat16LinearSrgb([0, 0, 0], 1)).toEqual(mul3(mul3([3.2406, -1.5372, -0.4986, -0.9689, 1.8758, 0.0415, 0.0557, -0.204, 1.057], IDENTITY3), SRGB_TO_XYZ));
  });
});

describe('the scene adopted white', () => {
  it('is the luminous-flux-weighted mix: 2700 K and 4000 K modules adapt to their mix, so each keeps its difference', () => {
    const warm = cctToLinearRgb(2700);
    const cool = cctToLinearRgb(4000);
    const white = adoptedWhite([lamp(1000, warm), lamp(3000, cool), lamp(3000, cool, 0)])!;
    // Weights: 1000 lm of 2700 K, 3000 lm of 4000 K (the third is off).
    for (let k = 0; k < 3; k++) expect(white[k]).toBeCloseTo((1000 * warm[k] + 3000 * cool[k]) / 4000, 10);
    expect(lum(white)).toBeCloseTo(1, 12);
    // Adapted to the mix, the 2700 K light stays warmer than the 4000 K light (R/B ratio).
    const m = adaptationFor({ kind: 'camera', cct: 3000 }, null, 0); // sanity: camera ignores the scene
    expect(m.white).toEqual(cctToLinearRgb(3000));
    const eye = adaptationFor({ kind: 'eye' }, white, 50).matrix;
    const a = mulVec3(eye, warm);
    const b = mulVec3(eye, cool);
    expect(a[0] / a[2]).toBeGreaterThan(1.3 * (b[0] / b[2]));
    // Dimming scales a lamp's weight.
    const dimmed = adoptedWhite([lamp(1000, warm), lamp(3000, cool, 1 / 3)])!;
    for (let k = 0; k < 3; k++) expect(dimmed[k]).toBeCloseTo((warm[k] + cool[k]) / 2, 10);
  });

  it('leaves out saturated gels (a red stage light is no white) but keeps CTO-like tints; null without white light', async () => {
    await loadColourFilterSpectra();
    const red = moduleColour(3000, 'lee-106').linearRgb as [number, number, number];
    expect(isWhiteLight(red)).toBe(false);
    expect(isWhiteLight(cctToLinearRgb(3000))).toBe(true);
    expect(adoptedWhite([lamp(1000, red)])).toBeNull();
    expect(adoptedWhite([])).toBeNull();
    expect(adoptedWhite([lamp(1000, cctToLinearRgb(3000), 0)])).toBeNull();
    const mixed = adoptedWhite([lamp(1000, red), lamp(500, cctToLinearRgb(3000))])!;
    cctToLinearRgb(3000).forEach((v, k) => expect(mixed[k]).toBeCloseTo(v, 10));
    // Eye adaptation with no white: nothing to adapt to.
    expect(adaptationFor({ kind: 'eye' }, null, 50)).toEqual({ matrix: IDENTITY3, d: 0, white: null });
  });
});

describe('the adopted white of a daylit room', () => {
  it("weighs daylight by the lumens entering through the windows (white: equal RGB) against the lamps' lumens; Electric, Daylight and Both each adapt to what is shown", async () => {
    // daylight-room.json: a clear June morning through a south window; one 2000 lm 2700 K lamp added.
    const input = await loadRenderInputAsync(new URL('../../fixtures/scenes/daylight-room.json', import.meta.url).pathname);
    const warm = cctToLinearRgb(2700);
    const scene = { ...input.bakeScene, luminaires: [lamp(2000, warm)] };
    const d = scene.daylight!;
    const lumens = daylightEnteringFlux(d, daylightWindows(scene.room.shape!, [0, 0, 0], d.glazing));
    // A clear sky with the sun brings far more light in than one lamp: tens of thousands of lumens.
    expect(lumens).toBeGreaterThan(10 * 2000);
    const both = sceneAdoptedWhite(scene, 'both')!;
    for (let k = 0; k < 3; k++) expect(both[k]).toBeCloseTo((lumens + 2000 * warm[k]) / (lumens + 2000 * lum(warm)), 10);
    // So by day the eye adapts close to daylight's white (the lamp then looks warm, as it does by day).
    expect(both[0] / both[2]).toBeLessThan(1.2);
    expect(both[0] / both[2]).toBeLessThan(0.5 * (warm[0] / warm[2]));
    console.log(`daylight-room.json, 10:00 on 21 June: ${lumens.toFixed(0)} lm through the window; adopted white R/B ${(both[0] / both[2]).toFixed(3)} (the 2700 K lamp alone ${(warm[0] / warm[2]).toFixed(3)})`);
    expect(sceneAdoptedWhite(scene, 'daylight')).toEqual([1, 1, 1]);
    sceneAdoptedWhite(scene, 'electric')!.forEach((v, k) => expect(v).toBeCloseTo(warm[k] / lum(warm), 10));
    // A room without daylight: the lamps alone, as before.
    expect(sceneAdoptedWhite({ ...scene, daylight: undefined }, 'both')).toEqual(adoptedWhite([lamp(2000, warm)]));
  });
});

describe('settings', () => {
  it('parse and format eye, none, camera:<K>; refuse anything else; L_A = 0.2 / auto exposure', () => {
    expect(parseAdaptation('eye')).toEqual({ kind: 'eye' });
    expect(parseAdaptation(' None ')).toEqual({ kind: 'none' });
    expect(parseAdaptation('camera:3000')).toEqual({ kind: 'camera', cct: 3000 });
    expect(parseAdaptation('camera:2700K')).toEqual({ kind: 'camera', cct: 2700 });
    for (const bad of ['', 'camera', 'camera:', 'camera:500', 'camera:30000', 'camera:abc', 'auto']) expect(parseAdaptation(bad)).toBeNull();
    expect(formatAdaptation({ kind: 'camera', cct: 3200 })).toBe('camera:3200');
    expect(formatAdaptation({ kind: 'eye' })).toBe('eye');
    // A room of L̄ = 47.75 cd/m² (300 lx on ρ 0.5): auto = 0.18 / 47.75, L_A = 0.2 · 47.75 / 0.18 = 53.05 cd/m².
    expect(adaptingLuminance(0.18 / ((0.5 * 300) / Math.PI))).toBeCloseTo(53.0516, 3);
    expect(adaptingLuminance(0)).toBe(0);
    expect(adaptingLuminance(Number.NaN)).toBe(0);
    expect(adaptationFor({ kind: 'none' }, cctToLinearRgb(3000), 50).matrix).toEqual(IDENTITY3);
  });
});
