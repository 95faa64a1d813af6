import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { integrateFlux, intensity, parsePhotometry, photometryWarnings } from '../../../src/core/photometry';
import { FIXTURE_DIR, loadFixture, loadReal, realFiles } from './helpers';

/** Non-fatal findings that used to pass silently (issue 18), as photometryWarnings() reports them. */

const ISO = readFileSync(`${FIXTURE_DIR}/c_rotational_isotropic.ies`, 'latin1');

describe('photometry warnings', () => {
  it('a 360° plane that differs from the 0° plane is said; the 0° plane is used', () => {
    const ph = loadFixture('c_full_360_seam_differs.ies');
    expect(photometryWarnings(ph)).toEqual(['the 360° plane differs from the 0° plane (by up to 30 cd, 16.7 % of their peak, at γ 0°); the 0° plane is used for both']);
    const same = loadFixture('c_full_360.ies');
    expect(photometryWarnings(same)).toEqual([]);
    // Everything but the dropped 360° plane is the same light.
    expect(ph.candela).toEqual(same.candela);
    expect(intensity(ph, 30, 360)).toBe(intensity(ph, 30, 0));
  });

  it('stated lumens 60× off the integrated flux are said; the integrated flux is what the model carries', () => {
    const ph = loadFixture('lumens_mismatch_60x.ies');
    expect(ph.statedLumens).toBe(34);
    expect(integrateFlux(ph)).toBeCloseTo(2047.1, 1);
    expect(photometryWarnings(ph)).toEqual(['stated lumens 34 lm and integrated flux 2047 lm differ by 5921 % (ratio 60.21); the integrated flux of the candela data is used']);
    // The file it was derived from states 2044 lm: no warning.
    expect(photometryWarnings(loadReal('bega_84693_narrow_spot.ies'))).toEqual([]);
  });

  it('relative photometry: a light output ratio above 1.05 or below 0.1 is said', () => {
    // Isotropic 100 cd = 1256.6 lm against 1000 lamp lumens: LOR 1.257.
    const high = parsePhotometry(ISO.replace('1 -1 1 19', '1 1000 1 19'), 'high.ies');
    expect(photometryWarnings(high)).toEqual(['integrated flux 1257 lm exceeds the stated lamp lumens 1000 lm (light output ratio 1.257 > 1); the candela data is used']);
    const low = parsePhotometry(ISO.replace('1 -1 1 19', '1 20000 1 19'), 'low.ies');
    expect(photometryWarnings(low)).toEqual(['integrated flux 1257 lm is only 6.283 % of the stated lamp lumens 20000 lm; the candela data is used']);
    expect(photometryWarnings(parsePhotometry(ISO.replace('1 -1 1 19', '1 1500 1 19'), 'ok.ies'))).toEqual([]);
  });

  it('angles listed in descending order are sorted with their values, and said', () => {
    const ph = loadFixture('descending_angles.ies');
    const ascending = loadFixture('version_2002.ies');
    expect(ph.candela).toEqual(ascending.candela);
    expect(ph.verticalAngles).toEqual(ascending.verticalAngles);
    expect(ph.horizontalAngles).toEqual(ascending.horizontalAngles);
    expect(photometryWarnings(ph)).toEqual([
      'the 10 vertical angles are listed in descending order; read in ascending order with their values',
      'the 4 horizontal angles are listed in descending order; read in ascending order with their planes',
    ]);
  });

  it('a TILT table listed in descending order is sorted with its factors', () => {
    const text = readFileSync(`${FIXTURE_DIR}/tilt_include.ies`, 'latin1').replace('0 45 90\n0.9 0.8 0.5', '90 45 0\n0.5 0.8 0.9');
    const ph = parsePhotometry(text, 't.ies');
    expect(ph.tilt).toEqual(loadFixture('tilt_include.ies').tilt);
    expect(photometryWarnings(ph)).toEqual(['the 3 tilt angles are listed in descending order; read in ascending order with their factors']);
  });

  it('a file whose every candela value is 0 is said', () => {
    const lines = ISO.split('\n');
    lines[11] = lines[11].replaceAll('100', '0');
    lines[12] = lines[12].replaceAll('100', '0');
    const dark = parsePhotometry(lines.join('\n'), 'dark.ies');
    expect(photometryWarnings(dark)).toEqual(['every candela value is 0: the luminaire emits no light']);
  });

  it('only the known, true warnings on the 30 shared files (no seam or lumens warning)', () => {
    for (const file of realFiles()) {
      const warnings = photometryWarnings(loadReal(file));
      for (const w of warnings) {
        expect(w).not.toMatch(/360° plane|stated lumens|lamp lumens|descending/);
        expect(w.length).toBeLessThanOrEqual(200);
      }
    }
  });

  it('photometryWarnings returns a copy without repeats', () => {
    const ph = { warnings: ['a', 'b', 'a'] };
    const list = photometryWarnings(ph);
    expect(list).toEqual(['a', 'b']);
    list.push('c');
    expect(ph.warnings).toEqual(['a', 'b', 'a']);
  });
});
