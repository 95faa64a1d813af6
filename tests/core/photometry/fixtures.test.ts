import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { InputError } from '../../../src/core/inputError';
import { integrateFlux, intensity, parsePhotometry, PhotometryParseError, tiltFactorAt } from '../../../src/core/photometry';
import { FIXTURE_DIR, loadFixture } from './helpers';

const cosd = (d: number): number => Math.cos((d * Math.PI) / 180);
const sind = (d: number): number => Math.sin((d * Math.PI) / 180);
const lambert = (g: number): number => 100 * Math.max(cosd(g), 0);

// The analytic distributions the fixtures were written from (see each file's
// [LUMINAIRE]); every shape has zero-mean modulation in C, so Φ = π · 100 lm.
const SYMMETRY_FIXTURES: Record<string, { symmetry: string; shape: (c: number) => number }> = {
  'c_quadrant.ies': { symmetry: 'quadrant', shape: (c) => 1 + 0.5 * cosd(2 * c) },
  'c_quadrant_90_180.ies': { symmetry: 'quadrant', shape: (c) => 1 + 0.5 * cosd(2 * c) },
  'c_bilateral_c0.ies': { symmetry: 'bilateral-c0', shape: (c) => 1 + 0.5 * cosd(c) },
  'c_bilateral_c90.ies': { symmetry: 'bilateral-c90', shape: (c) => 1 + 0.5 * sind(c) },
  'c_full_360.ies': { symmetry: 'none', shape: (c) => 1 + 0.5 * cosd(c) + 0.3 * sind(2 * c) },
  'c_full_345.ies': { symmetry: 'none', shape: (c) => 1 + 0.5 * cosd(c) + 0.3 * sind(2 * c) },
};

describe('symmetry fixtures (type C)', () => {
  for (const [file, { symmetry, shape }] of Object.entries(SYMMETRY_FIXTURES)) {
    it(`${file}: ${symmetry}, exact at measured nodes everywhere on the circle`, () => {
      const ph = loadFixture(file);
      expect(ph.symmetry).toBe(symmetry);
      // Every 15° plane (the file's spacing, unfolded) and 10° vertical step is a node.
      for (let c = 0; c <= 360; c += 15) {
        for (let g = 0; g <= 90; g += 10) expect(intensity(ph, g, c)).toBeCloseTo(lambert(g) * shape(c), 2);
      }
      // Between nodes: bilinear error of a 10° × 15° grid on these smooth shapes < 4 cd.
      for (let k = 0; k < 200; k++) {
        const g = (k * 37) % 90;
        const c = (k * 53.7) % 360;
        expect(Math.abs(intensity(ph, g, c) - lambert(g) * shape(c))).toBeLessThan(4);
      }
      // Nothing above the measured 0..90 range (zero rows padded just beyond 90).
      expect(intensity(ph, 91, 33)).toBe(0);
      // Φ = π·100; the 10° linear interpolation of cos γ under-counts by 0.25 %.
      expect(integrateFlux(ph) / (Math.PI * 100)).toBeCloseTo(0.9975, 3);
    });
  }

  it('isotropic source: Φ = 4π·I to 1e-6 relative', () => {
    const ph = loadFixture('c_rotational_isotropic.ies');
    expect(ph.symmetry).toBe('rotational');
    expect(Math.abs(integrateFlux(ph) / (4 * Math.PI * 100) - 1)).toBeLessThan(1e-6);
  });

  it('vertical range 90..180 (uplight) is padded with zeros below', () => {
    const ph = loadFixture('c_uplight_90_180.ies');
    expect(ph.verticalAngles[0]).toBe(0);
    expect(intensity(ph, 45, 0)).toBe(0);
    expect(intensity(ph, 89, 0)).toBe(0);
    expect(intensity(ph, 180, 0)).toBeCloseTo(100, 6);
    expect(integrateFlux(ph) / (Math.PI * 100)).toBeCloseTo(0.9975, 3);
  });
});

describe('interpolation seams', () => {
  const d = 1e-7;
  it('C = 0/360 is continuous (full grid and a grid ending at 345)', () => {
    for (const file of ['c_full_360.ies', 'c_full_345.ies']) {
      const ph = loadFixture(file);
      for (const g of [5, 33, 60, 85]) {
        const at0 = intensity(ph, g, 0);
        expect(intensity(ph, g, 360 - d)).toBeCloseTo(at0, 4);
        expect(intensity(ph, g, d)).toBeCloseTo(at0, 4);
        expect(intensity(ph, g, 360)).toBeCloseTo(at0, 12);
        expect(intensity(ph, g, -720)).toBeCloseTo(at0, 12);
      }
      // Between 345 and 360 the 345 file interpolates toward the 0 plane.
      const ph345 = loadFixture('c_full_345.ies');
      const mid = intensity(ph345, 40, 352.5);
      expect(mid).toBeCloseTo((intensity(ph345, 40, 345) + intensity(ph345, 40, 0)) / 2, 9);
    }
  });

  it('mirror seams: quadrant at 90/180/270, bilateral at 0/180 and 90/270', () => {
    const q = loadFixture('c_quadrant.ies');
    const b0 = loadFixture('c_bilateral_c0.ies');
    const b90 = loadFixture('c_bilateral_c90.ies');
    for (const g of [10, 47, 80]) {
      for (const x of [0.3, 7, 22.5, 44]) {
        expect(intensity(q, g, 90 - x)).toBeCloseTo(intensity(q, g, 90 + x), 9);
        expect(intensity(q, g, 180 - x)).toBeCloseTo(intensity(q, g, 180 + x), 9);
        expect(intensity(q, g, 270 - x)).toBeCloseTo(intensity(q, g, 270 + x), 9);
        expect(intensity(b0, g, x)).toBeCloseTo(intensity(b0, g, 360 - x), 9);
        expect(intensity(b0, g, 180 - x)).toBeCloseTo(intensity(b0, g, 180 + x), 9);
        expect(intensity(b90, g, 90 - x)).toBeCloseTo(intensity(b90, g, 90 + x), 9);
        expect(intensity(b90, g, 270 - x)).toBeCloseTo(intensity(b90, g, 270 + x), 9);
      }
      // Continuity across each seam itself.
      for (const c of [90, 180, 270]) expect(intensity(q, g, c + d)).toBeCloseTo(intensity(q, g, c - d), 4);
    }
  });

  it('γ outside 0..180 is the same direction through the pole', () => {
    const ph = loadFixture('c_full_360.ies');
    expect(intensity(ph, -30, 10)).toBeCloseTo(intensity(ph, 30, 190), 12);
    expect(intensity(ph, 390, 10)).toBeCloseTo(intensity(ph, 30, 10), 12);
    expect(intensity(ph, 200, 10)).toBeCloseTo(intensity(ph, 160, 190), 12);
    expect(intensity(ph, Number.NaN, 0)).toBe(0);
  });
});

describe('photometric types A and B', () => {
  // Both fixtures hold I = 100·cos H·cos V, which in either coordinate system is
  // 100 × (component along the aim axis): a Lambertian emitter facing the aim,
  // i.e. I(γ, C) = 100·cos γ after conversion (aim → nadir), for every C.
  for (const file of ['type_b.ies', 'type_a.ies']) {
    it(`${file} converts to I(γ, C) = 100 cos γ`, () => {
      const ph = loadFixture(file);
      expect(ph.photometricType).toBe(file === 'type_b.ies' ? 'B' : 'A');
      for (let k = 0; k < 300; k++) {
        const g = (k * 7.3) % 180;
        const c = (k * 31.1) % 360;
        expect(Math.abs(intensity(ph, g, c) - lambert(g))).toBeLessThan(1.6);
      }
      expect(integrateFlux(ph) / (Math.PI * 100)).toBeGreaterThan(0.99);
      expect(integrateFlux(ph) / (Math.PI * 100)).toBeLessThan(1.001);
    });
  }

  it('type B axes: lateral H → C0, vertical V → C90 (documented frame)', () => {
    // A type-B file with light only at H = 30, V = 0 (and mirrored H = −30).
    const text = readFileSync(`${FIXTURE_DIR}/type_b.ies`, 'latin1');
    const lines = text.split('\n');
    const tilt = lines.findIndex((l) => l.startsWith('TILT'));
    const head = lines.slice(0, tilt + 3).join('\n');
    const vs = Array.from({ length: 19 }, (_, i) => -90 + i * 10);
    const hs = [0, 10, 20, 30, 40, 50, 60, 70, 80, 90];
    const rows = hs.map((h) => vs.map((v) => (h === 30 && v === 0 ? 1000 : 0)).join(' '));
    const ph = parsePhotometry(`${head}\n${vs.join(' ')}\n${hs.join(' ')}\n${rows.join('\n')}\n`, 'spot.ies');
    expect(intensity(ph, 30, 0)).toBeCloseTo(1000, 6); // H = +30 → γ 30 in C0
    expect(intensity(ph, 30, 180)).toBeCloseTo(1000, 6); // H = −30 (mirror) → C180
    expect(intensity(ph, 30, 90)).toBe(0); // V = 30 → C90, dark here
  });
});

describe('TILT, multipliers, versions, units', () => {
  it('TILT=INCLUDE applies the factor for tilt 0 and keeps the table', () => {
    const ph = loadFixture('tilt_include.ies');
    expect(intensity(ph, 45, 0)).toBeCloseTo(90, 9);
    expect(ph.tilt).toEqual({ lampToLuminaireGeometry: 1, angles: [0, 45, 90], factors: [0.9, 0.8, 0.5] });
    expect(tiltFactorAt(ph.tilt!, 67.5)).toBeCloseTo(0.65, 12);
    expect(tiltFactorAt(ph.tilt!, 120)).toBe(0.5);
  });

  it('TILT=<file> reads the supplied file, and fails clearly without it', () => {
    expect(intensity(loadFixture('tilt_file.ies'), 10, 0)).toBeCloseTo(75, 9);
    const bytes = readFileSync(`${FIXTURE_DIR}/tilt_file.ies`);
    expect(() => parsePhotometry(bytes, 'tilt_file.ies')).toThrow('tilt_file.ies line 6: TILT=lamp_tilt.tlt refers to a separate tilt file that was not supplied');
  });

  it('candela multiplier and relative lumens', () => {
    const ph = loadFixture('relative_multiplier.ies');
    expect(intensity(ph, 0, 0)).toBe(50); // 25 × multiplier 2
    expect(ph.statedLumens).toBe(1000);
    expect(ph.absolute).toBe(false);
    expect(integrateFlux(ph)).toBeCloseTo(4 * Math.PI * 50, 6);
    // The file says width 0.3, length 0.6: LM-63's length runs along 0°–180°, stored as width (local x).
    expect(ph.luminousOpening).toEqual({ width: 0.6, length: 0.3, height: 0, shape: 'rectangular' });
  });

  it('all five LM-63 versions give the same model', () => {
    const versions = ['1986', '1991', '1995', '2002', '2019'];
    const parsed = versions.map((v) => loadFixture(`version_${v}.ies`));
    parsed.forEach((ph, i) => {
      expect(ph.version).toBe(`LM-63-${versions[i]}`);
      expect(ph.candela).toEqual(parsed[0].candela);
      expect(ph.verticalAngles).toEqual(parsed[0].verticalAngles);
      expect(ph.horizontalAngles).toEqual(parsed[0].horizontalAngles);
      // Units 1 (feet): a 0.5 ft circular opening is 0.1524 m across.
      expect(ph.luminousOpening.shape).toBe('circular');
      expect(ph.luminousOpening.width).toBeCloseTo(0.1524, 12);
    });
    expect(parsed[0].manufacturer).toBe('ACME LIGHTING');
    expect(parsed[0].luminaire).toBe('DOWNLIGHT 1986');
    expect(parsed[2].keywords.LUMINAIRE).toBe('version 1995 continued text');
    expect(parsed[4].keywords.FILEGENINFO).toBe('hand-written');
  });

  it('tolerates CRLF, Latin-1, commas, split lines, blank lines, leading spaces, END and Ctrl-Z', () => {
    const ph = loadFixture('tolerant_mixed.ies');
    expect(ph.manufacturer).toBe('Leuchten Müller');
    expect(ph.luminaire).toBe('30° spot second line');
    expect(ph.inputWatts).toBe(12);
    expect(ph.symmetry).toBe('quadrant');
    expect(intensity(ph, 30, 90)).toBe(87);
    expect(ph.warnings).toEqual(['ignored 1 trailing item(s) after the data from line 18 ("END")']);
  });

  it('decodes UTF-8 when valid and Latin-1 otherwise', () => {
    const base = readFileSync(`${FIXTURE_DIR}/c_rotational_isotropic.ies`, 'latin1').replace('[MANUFAC] luxbox test', '[MANUFAC] Müller');
    expect(parsePhotometry(new TextEncoder().encode(base), 'u.ies').manufacturer).toBe('Müller');
    expect(parsePhotometry(Buffer.from(base, 'latin1'), 'l.ies').manufacturer).toBe('Müller');
  });
});

describe('EULUMDAT symmetry indicators 0–4', () => {
  const shapes = [(c: number) => 1 + 0.5 * cosd(c) + 0.3 * sind(2 * c), () => 1, (c: number) => 1 + 0.5 * cosd(c), (c: number) => 1 + 0.5 * sind(c), (c: number) => 1 + 0.5 * cosd(2 * c)];
  const names = ['none', 'rotational', 'bilateral-c0', 'bilateral-c90', 'quadrant'];
  shapes.forEach((shape, isym) => {
    it(`Isym ${isym} (${names[isym]}) unfolds to the written distribution`, () => {
      const ph = loadFixture(`ldt_isym${isym}.ldt`);
      expect(ph.format).toBe('LDT');
      expect(ph.symmetry).toBe(names[isym]);
      // 300 cd/klm·cos γ·shape(C) at 1000 lm lamp flux.
      for (let c = 0; c < 360; c += 15) {
        for (let g = 0; g <= 90; g += 5) expect(intensity(ph, g, c)).toBeCloseTo(300 * cosd(g) * shape(c), 2);
      }
      expect(ph.statedLumens).toBe(1000);
      expect(integrateFlux(ph) / (Math.PI * 300)).toBeCloseTo(0.9994, 3);
    });
  });
});

describe('malformed files', () => {
  const CASES: Record<string, string> = {
    'vertical_count_mismatch.ies': 'vertical_count_mismatch.ies line 8: expected 7 vertical angles, found 5 before 0',
    'non_monotonic.ies': 'non_monotonic.ies line 7: expected 5 vertical angles, found 3 before 20, which does not ascend after 30',
    'negative_candela.ies': 'negative_candela.ies line 9: negative candela value -80 at horizontal angle 0, vertical angle 20',
    'nan_candela.ies': 'nan_candela.ies line 9: expected 5 candela values, found 2: expected a candela value, found "NaN"',
    'absurd_count.ies': 'absurd_count.ies line 5: 100000000 vertical angles exceed the limit of 3601',
    'truncated.ies': 'truncated.ies line 10: expected 10 candela values, found 7 (the file ends early)',
    'tilt_file_missing.ies': 'tilt_file_missing.ies line 4: TILT=lamp.tlt refers to a separate tilt file that was not supplied',
    'no_tilt_line.ies': 'no_tilt_line.ies: no "TILT=" line found: not an IES LM-63 file',
    'too_many_values.ies': 'too_many_values.ies line 10: 10 numbers follow the candela table: the angle counts in the header do not match the data',
    'bad_photometric_type.ies': 'bad_photometric_type.ies line 5: photometric type must be 1 (C), 2 (B) or 3 (A), found 4',
    'unsupported_horizontal_range.ies': 'unsupported_horizontal_range.ies line 8: unsupported horizontal angle range 0..45',
    'zero_multiplier.ies': 'zero_multiplier.ies line 5: candela multiplier must be positive, found 0',
    'vertical_out_of_range.ies': 'vertical_out_of_range.ies line 7: vertical angle 190 is outside 0..180',
    'empty.ies': 'empty.ies: the file is empty',
    'ldt_bad_isym.ldt': 'ldt_bad_isym.ldt line 3: symmetry indicator Isym must be 0..4, found 7',
    'ldt_truncated.ldt': 'ldt_truncated.ldt line 60: expected 24 C-plane angles, found 18 (the file ends early)',
    'ldt_absurd_count.ldt': 'ldt_absurd_count.ldt line 4: the number of C-planes Mc 99999999 exceeds the limit of 3601',
  };
  for (const [file, message] of Object.entries(CASES)) {
    it(`${file} → "${message}"`, () => {
      let caught: unknown;
      try {
        parsePhotometry(readFileSync(`${FIXTURE_DIR}/bad/${file}`), file);
      } catch (error) {
        caught = error;
      }
      expect(caught).toBeInstanceOf(PhotometryParseError);
      expect(caught).toBeInstanceOf(InputError);
      expect((caught as Error).message.startsWith(message)).toBe(true);
      expect((caught as Error).message).not.toContain('\n');
    });
  }
});
