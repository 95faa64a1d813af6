/**
 * The crossfade's easing (src/core/model/cues/sceneFade.ts): even steps of CIE L* of the total output,
 * checked against hand-computed values; linear when both scenes give the same output.
 */
import { describe, expect, it } from 'vitest';
import { fadeFraction, fadeLevels, levelsOutput, lightness, luminanceOfLightness, luminousOutput, mixLevels, mixLights, outputLevels } from '../../../../src/core/model/cues/sceneFade';
import { allModules } from '../../../../src/core/model/cues/lightScenes';
import { catalog, run, withPreset } from '../helpers';

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
    const others = allModules(from)
      .filter((m) => m.id !== a.id && m.id !== b.id)
      .reduce((s, m) => s + m.dimming * lumens(m), 0);
    expect(luminousOutput(to, catalog)).toBeCloseTo(0.2 * lumens(a) + others, 9);
  });
});

describe('a fade that starts in the middle of another (a console cue fades from the current state)', () => {
  // Three spots of the same beam (lumens L each). Old fade A → B of equal output (L): e = t, so at
  // t = 0.5 the mix is m1 0.5, m2 0.5, m3 0. The new fade goes to C = m2 1, m3 1 (output 2 L).
  const a = new Map([
    ['m1', 1],
    ['m2', 0],
    ['m3', 0],
  ]);
  const b = new Map([
    ['m1', 0],
    ['m2', 1],
    ['m3', 0],
  ]);
  const c = new Map([
    ['m1', 0],
    ['m2', 1],
    ['m3', 1],
  ]);

  it('the mix at the instant, then the new fade at t = 0, 0.5, 1 against hand-computed levels', () => {
    expect(fadeFraction(0.5, 1, 1)).toBe(0.5); // equal outputs cross linearly
    const shown = mixLevels(a, b, 0.5);
    expect([...shown]).toEqual([
      ['m1', 0.5],
      ['m2', 0.5],
      ['m3', 0],
    ]);
    // Outputs relative to L: from 0.5 + 0.5 = 1, to 2; Yn = 2. L*(1/2) = 116·0.5^(1/3) − 16 = 76.069261,
    // L*(1) = 100; halfway L* = 88.034631 → f = 104.034631 / 116 = 0.896850, Y/Yn = f³ = 0.721373,
    // e(0.5) = (2·0.721373 − 1) / (2 − 1) = 0.442746.
    const e = [0, 0.5, 1].map((t) => fadeFraction(t, 1, 2));
    expect(e[0]).toBe(0);
    expect(e[1]).toBeCloseTo(0.442746, 6);
    expect(e[2]).toBe(1);
    const at = e.map((x) => [...mixLevels(shown, c, x)].map(([, v]) => v));
    expect(at[0]).toEqual([0.5, 0.5, 0]); // t = 0: exactly the look on screen, not B's end state (0, 1, 0)
    // t = 0.5: m1 0.5·(1 − e) = 0.278627, m2 0.5 + 0.5·e = 0.721373, m3 e = 0.442746.
    expect(at[1][0]).toBeCloseTo(0.278627, 6);
    expect(at[1][1]).toBeCloseTo(0.721373, 6);
    expect(at[1][2]).toBeCloseTo(0.442746, 6);
    expect(at[2]).toEqual([0, 1, 1]);
  });

  it('the output of levels is linear in them: the mix of two outputs is the output of the mix', () => {
    const config = withPreset('single', 1, 1);
    const ids = allModules(config).map((m) => m.id);
    const lumens = luminousOutput(config, catalog) / 3; // three equal spots at level 1
    const rename = (m: Map<string, number>) => new Map([...m].map(([k, v]) => [ids[Number(k.slice(1)) - 1], v]));
    expect(levelsOutput(rename(mixLevels(a, b, 0.5)), config, catalog)).toBeCloseTo(lumens, 9);
    expect(levelsOutput(rename(c), config, catalog)).toBeCloseTo(2 * lumens, 9);
    expect(outputLevels(config)).toEqual(new Map(ids.map((id) => [id, 1])));
  });

  it('lights mix as the baker weights them: dimming × colour, linear in e', () => {
    // A: dimming 1, colour (1, 0.8, 0.6); B: dimming 0.5, colour (0.6, 0.8, 1); e = 0.5.
    // Weight 0.5·(1, 0.8, 0.6) + 0.5·0.5·(0.6, 0.8, 1) = (0.65, 0.6, 0.55); dimming 0.75; colour = weight / 0.75.
    const mixed = mixLights(new Map([['m1', { dimming: 1, color: [1, 0.8, 0.6] as [number, number, number] }]]), new Map([['m1', { dimming: 0.5, color: [0.6, 0.8, 1] as [number, number, number] }]]), 0.5).get('m1')!;
    expect(mixed.dimming).toBeCloseTo(0.75, 12);
    expect(mixed.color[0]).toBeCloseTo(0.65 / 0.75, 12);
    expect(mixed.color[1]).toBeCloseTo(0.8, 12);
    expect(mixed.color[2]).toBeCloseTo(0.55 / 0.75, 12);
    // Both dark: the target colour (it does not show).
    expect(mixLights(new Map([['m1', { dimming: 0, color: [1, 0, 0] as [number, number, number] }]]), new Map([['m1', { dimming: 0, color: [0, 0, 1] as [number, number, number] }]]), 0.3).get('m1')).toEqual({
      dimming: 0,
      color: [0, 0, 1],
    });
  });
});
