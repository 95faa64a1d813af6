import { describe, expect, it } from 'vitest';
import { daylightFactor, daylightFactorStatistics, EN17037_MINIMUM, targetDaylightFactor } from '../../../src/core/daylight/daylightFactor';

describe('daylight factor statistics', () => {
  it('defines DF and EN 17037 target factors', () => {
    expect(daylightFactor(200, 10000)).toBeCloseTo(2, 12);
    expect(targetDaylightFactor(300, 15000)).toBeCloseTo(2, 12);
  });

  it('matches the analytic statistics of DF(x) = 5 e^{−x/2} over a 6 m deep plane', () => {
    const n = 6000;
    const values = Array.from({ length: n }, (_, i) => 5 * Math.exp(-((i + 0.5) * 6) / n / 2));
    const s = daylightFactorStatistics(values);
    const average = ((5 * 2) / 6) * (1 - Math.exp(-3));
    expect(s.average).toBeCloseTo(average, 5);
    expect(s.minimum).toBeCloseTo(5 * Math.exp(-3), 3);
    expect(s.maximum).toBeCloseTo(5, 2);
    expect(s.uniformity).toBeCloseTo((5 * Math.exp(-3)) / average, 3);
    // DF ≥ 2 where x ≤ 2 ln 2.5; DF ≥ 0.7 where x ≤ 2 ln(5/0.7).
    expect(s.shareAtTarget).toBeCloseTo((2 * Math.log(2.5)) / 6, 3);
    expect(s.shareAtMinimumTarget).toBeCloseTo((2 * Math.log(5 / 0.7)) / 6, 3);
    expect(s.median).toBeCloseTo(5 * Math.exp(-1.5), 2);
    expect(s.meetsTargets).toBe(false);
  });

  it('weights values by area and judges the EN 17037 minimum level', () => {
    // 60 % of the area at 3 %, 38 % at 1 %, 2 % at 0.5 %.
    const s = daylightFactorStatistics([3, 1, 0.5], [0.6, 0.38, 0.02]);
    expect(s.average).toBeCloseTo(0.6 * 3 + 0.38 + 0.01, 12);
    expect(s.shareAtTarget).toBeCloseTo(0.6, 12);
    expect(s.shareAtMinimumTarget).toBeCloseTo(0.98, 12);
    expect(s.meetsTargets).toBe(true);
    expect(daylightFactorStatistics([3, 1, 0.5], [0.6, 0.34, 0.06]).meetsTargets).toBe(false);
    expect(daylightFactorStatistics([3, 1, 0.5], [0.6, 0.38, 0.02], { ...EN17037_MINIMUM, target: 3.5 }).meetsTargets).toBe(false);
    expect(s.median).toBe(3);
  });

  it('refuses empty, mismatched and non-finite input', () => {
    expect(() => daylightFactorStatistics([])).toThrow(/at least one/);
    expect(() => daylightFactorStatistics([1, 2], [1])).toThrow(/2 values but 1 weights/);
    expect(() => daylightFactorStatistics([1, NaN])).toThrow(/value 1/);
    expect(() => daylightFactorStatistics([1], [0])).toThrow(/positive total weight/);
  });
});
