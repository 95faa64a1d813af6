/**
 * The crossfade's easing (src/core/model/sceneFade.ts): even steps of CIE L* of the total output,
 * checked against hand-computed values; linear when both scenes give the same output.
 */
import { describe, expect, it } from 'vitest';
import { fadeFraction, fadeLevels, lightness, luminanceOfLightness, luminousOutput } from '../../../src/core/model/sceneFade';
import { allModules } from '../../../src/core/model/lightScenes';
import { catalog, run, withPreset } from './helpers';

describe('CIE L*', () => {
  it('matches CIE 15:2004 at hand-computed points and inverts', () => {
    expect(lightness(1)).toBeCloseTo(100, 12);
    expect(lightness(0)).toBeCloseTo(0, 12);
    // 0.18 (mid grey): 116·0.18^(1/3) − 16 = 49.4961
    expect(lightness(0.18)).toBeCloseTo(49.4961, 3);
    // Below (6/29)³ = 0.008856: L* = 903.2963·y
    expect(lightness(0.005)).toBeCloseTo(4.51648, 4);
    for (const y of [0, 0.001, 0.008856, 0.05, 0.5, 1]) expect(luminanceOfLightness(lightness(y))).toBeCloseTo(y, 12);
  });
});

describe('fade fraction', () => {
  it('is t between scenes of equal output, and 0 / 1 at the ends', () => {
    for (const t of [0, 0.25, 0.5, 0.75, 1]) expect(fadeFraction(t, 800, 800)).toBeCloseTo(t, 12);
    expect(fadeFraction(0, 0, 1000)).toBe(0);
    expect(fadeFraction(1, 0, 1000)).toBe(1);
    expect(fadeFraction(-1, 0, 1000)).toBe(0);
    expect(fadeFraction(2, 0, 1000)).toBe(1);
  });

  it('from black: L* rises linearly, so e(0.5) = Y at L* 50 = 0.18419; to black mirrors it', () => {
    // L* = 50 → f = 66/116 = 0.568966, Y = f³ = 0.184187 (by hand).
    expect(fadeFraction(0.5, 0, 1000)).toBeCloseTo(0.184187, 5);
    expect(fadeFraction(0.5, 1000, 0)).toBeCloseTo(1 - 0.184187, 5);
    // Half the output to full: L*(0.5) = 76.0693, t = 0.5 → L* 88.0347 → f = 0.896851, Y = f³ = 0.721373 → e = 0.442746
    expect(fadeFraction(0.5, 500, 1000)).toBeCloseTo(0.442746, 5);
  });

  it('is monotonic in t', () => {
    let last = -1;
    for (let t = 0; t <= 1.0000001; t += 0.01) {
      const e = fadeFraction(t, 120, 2500);
      expect(e).toBeGreaterThanOrEqual(last);
      last = e;
    }
  });
});

describe('levels shown during a fade', () => {
  it('interpolate each module’s output level (off = 0) and total output counts only modules that are on', () => {
    const from = withPreset('single', 1, 1);
    const [a, b] = allModules(from);
    let to = run(from, 'setModuleDimming', { moduleId: a.id, dimming: 0.2 });
    to = run(to, 'setModuleOn', { moduleId: b.id, on: false });
    const mid = fadeLevels(from, to, 0.25);
    expect(mid.get(a.id)).toBeCloseTo(0.75 * a.dimming + 0.25 * 0.2, 12);
    expect(mid.get(b.id)).toBeCloseTo(0.75 * b.dimming, 12);
    const lumens = (m: typeof a) => catalog.moduleTypes.find((t) => t.id === m.type)!.beams.find((x) => x.id === m.beam)!.lumens;
    const others = allModules(from).filter((m) => m.id !== a.id && m.id !== b.id).reduce((s, m) => s + m.dimming * lumens(m), 0);
    expect(luminousOutput(to, catalog)).toBeCloseTo(0.2 * lumens(a) + others, 9);
  });
});
