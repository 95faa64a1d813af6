import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { chooseQuality, FIRST_LIT_TARGET_MS, levelTexels, predictQuality, SOLVE_TARGET_MS, TYPICAL_QUALITY_SCENE, type BakeCalibration } from '../../../src/engines/relight/calibrateBakeSpeed';
import { QUALITY_LEVEL_NAMES, QUALITY_LEVELS } from '../../../src/engines/relight/qualityLevels';

const device = (msPerTexelSample: number, msPerTexelSource: number, directCompileMs = 0, msPerTexelBasis = 0, compileMs = 0): BakeCalibration => ({
  msPerTexelSample,
  msPerTexelSource,
  msPerTexelBasis,
  directCompileMs,
  compileMs,
  renderer: 'test',
  work: { texels: 19200, pointSources: 10, samples: 32, bounces: 1 },
});
const rank = (level: string) => QUALITY_LEVEL_NAMES.indexOf(level as never);

describe('quality levels: predicted cost', () => {
  it('counts the texels of the six surface maps at each level (5 × 4 × 2.8 m room)', () => {
    // fast 0.1 m: 50×40 floor/ceiling, 50×28 north/south, 40×28 west/east = 2·2000 + 2·1400 + 2·1120
    expect(levelTexels(TYPICAL_QUALITY_SCENE.room, 'fast')).toBe(2 * 2000 + 2 * 1400 + 2 * 1120);
    // balanced 0.05 m: 100×80, 100×56, 80×56
    expect(levelTexels(TYPICAL_QUALITY_SCENE.room, 'balanced')).toBe(2 * 8000 + 2 * 5600 + 2 * 4480);
  });

  it('predicts first lit = compile + photometries × direct compile + groups × texels × (sources × cost + basis cost), solve = solves × texels × samples × bounces × cost', () => {
    const cal = device(1e-4, 2e-5, 50, 3e-4, 120);
    const scene = { room: { width: 4, height: 2.5, depth: 3 }, groups: 3, pointSourcesPerGroup: 5, photometries: 2, indirectSolves: 2 };
    for (const p of predictQuality(cal, scene)) {
      const s = resolveBakeSettings(QUALITY_LEVELS[p.level]);
      expect(p.firstLitMs).toBeCloseTo(120 + 2 * 50 + 3 * p.texels * (5 * 2e-5 + 3e-4), 9);
      expect(p.solveMs).toBeCloseTo(2 * p.texels * s.samples * s.bounces * 1e-4, 9);
    }
  });
});

describe('chooseQuality', () => {
  it('gives a fast device "best" and a slow one "fast"', () => {
    // A discrete GPU: 1 ns per texel-sample, 0.1 ns per texel-source.
    expect(chooseQuality(device(1e-6, 1e-7))).toBe('best');
    // Software GL on a busy phone: 1 µs per texel-sample, 10 µs per texel-source.
    expect(chooseQuality(device(1e-3, 1e-2))).toBe('fast');
  });

  it('picks the best level within both targets, and "balanced" where only "best" misses', () => {
    const [, balanced, best] = predictQuality(device(1, 1), TYPICAL_QUALITY_SCENE);
    // Costs chosen so that balanced's solve takes 90 % of the target and best's 110 % (first lit well inside).
    const ratio = best.solveMs / balanced.solveMs;
    const perSample = (0.9 * SOLVE_TARGET_MS) / balanced.solveMs;
    expect(ratio * 0.9).toBeGreaterThan(1); // best is more than 1/0.9 times balanced's solve
    const perSource = (0.1 * FIRST_LIT_TARGET_MS) / best.firstLitMs;
    expect(chooseQuality(device(perSample, perSource))).toBe('balanced');
    expect(chooseQuality(device((perSample * 0.5) / ratio, perSource))).toBe('best');
  });

  it('refuses a calibration without finite costs (a stored one from another version), naming the field', () => {
    const stale = { ...device(1e-4, 1e-5), directCompileMs: undefined } as unknown as BakeCalibration;
    expect(() => chooseQuality(stale)).toThrow(/directCompileMs is undefined/);
    expect(() => chooseQuality(device(Number.NaN, 1e-5))).toThrow(/msPerTexelSample is NaN/);
    expect(() => chooseQuality(device(1e-4, -1))).toThrow(/msPerTexelSource is -1/);
  });

  it('never gives a device that is at least as fast in every cost a lower level (monotone)', () => {
    const cost = fc.double({ min: 1e-8, max: 1e-2, noNaN: true });
    const factor = fc.double({ min: 0, max: 1, noNaN: true });
    fc.assert(
      fc.property(cost, cost, fc.double({ min: 0, max: 2000, noNaN: true }), cost, factor, factor, factor, factor, fc.integer({ min: 1, max: 20 }), fc.integer({ min: 1, max: 64 }), (a, b, compile, c, fa, fb, fc2, fd, groups, sources) => {
        const scene = { ...TYPICAL_QUALITY_SCENE, groups, pointSourcesPerGroup: sources, photometries: Math.min(groups, 5) };
        const slow = device(a, b, compile, c, compile);
        const fast = device(a * fa, b * fb, compile * fc2, c * fd, compile * fc2);
        expect(rank(chooseQuality(fast, scene))).toBeGreaterThanOrEqual(rank(chooseQuality(slow, scene)));
      }),
      { seed: 15, numRuns: 500 },
    );
  });
});
