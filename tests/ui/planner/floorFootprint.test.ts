import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import { floorFootprint } from '../../../src/ui/planner/floorFootprint';

const iso = parsePhotometry(['IESNA:LM-63-2002', 'TILT=NONE', '1 1000 1 3 1 1 2 0 0 0', '1 1 10', '0 90 180', '0', '79.577 79.577 79.577'].join('\n'), 'iso.ies');
const real = (name: string) => parsePhotometry(readFileSync(`public/ies/${name}`), name);

describe('floorFootprint (half-maximum floor illuminance, units of mounting height)', () => {
  it('an isotropic source: E ∝ cos³γ halves at tan(acos(0.5^(1/3))) = 0.76642 h, a circle', () => {
    const f = floorFootprint(iso)!;
    const expected = Math.tan(Math.acos(Math.cbrt(0.5)));
    expect(f.peak).toEqual([0, 0]);
    for (const [u, v] of f.polygon) expect(Math.hypot(u, v)).toBeCloseTo(expected, 2);
  });

  it('the BEGA narrow spot stays within its beam cone (half-intensity at ~6° from nadir)', () => {
    const f = floorFootprint(real('bega_84693_narrow_spot.ies'))!;
    const radii = f.polygon.map(([u, v]) => Math.hypot(u - f.peak[0], v - f.peak[1]));
    const mean = radii.reduce((a, b) => a + b, 0) / radii.length;
    // E differs from I by cos³γ ≈ 0.98 at 6°, so the E contour sits just inside tan 6° = 0.105.
    expect(mean).toBeGreaterThan(0.07);
    expect(mean).toBeLessThan(0.115);
  });

  it('the ERCO wall washer lights a patch off to the C0 side, not under the lamp', () => {
    const f = floorFootprint(real('erco_kubus_floor_washlight.ies'))!;
    expect(f.peak[0]).toBeGreaterThan(0.2);
    expect(Math.abs(f.peak[1])).toBeLessThan(0.05);
    const centroidU = f.polygon.reduce((a, p) => a + p[0], 0) / f.polygon.length;
    expect(centroidU).toBeGreaterThan(0.2);
  });

  it('returns null for a luminaire that sends nothing downward', () => {
    const up = parsePhotometry(['IESNA:LM-63-2002', 'TILT=NONE', '1 1000 1 3 1 1 2 0 0 0', '1 1 10', '0 90 180', '0', '0 0 100'].join('\n'), 'up.ies');
    expect(floorFootprint(up)).toBeNull();
  });
});
