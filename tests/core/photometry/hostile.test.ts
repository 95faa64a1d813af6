import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { integrateFlux, intensity, MAX_PHOTOMETRY_BYTES, parsePhotometry, PhotometryParseError, type Photometry } from '../../../src/core/photometry';
import { isDecimal, readDecimal } from '../../../src/core/photometry/decimal';
import { FIXTURE_DIR, loadFixture, loadReal } from './helpers';

/** Regression tests for each class of hostile input found in issue 18. */

const ISO = readFileSync(`${FIXTURE_DIR}/c_rotational_isotropic.ies`, 'latin1');
const LDT = readFileSync('public/ies/zumtobel_arcos3_spot_isym1.ldt', 'latin1');
const LDT_NL = LDT.includes('\r\n') ? '\r\n' : '\n';

/** The isotropic fixture with its luminaire line (10 values) and ballast line (3 values) replaced. */
function iso(header = '1 -1 1 19 1 1 2 0 0 0', ballast = '1 1 10', candela?: string): string {
  const lines = ISO.split('\n');
  lines[6] = header;
  lines[7] = ballast;
  if (candela !== undefined) lines[11] = candela;
  return lines.join('\n');
}

/** The Zumtobel LDT with 0-based line `index` replaced. */
function ldtWith(index: number, text: string): string {
  const lines = LDT.split(LDT_NL);
  lines[index] = text;
  return lines.join(LDT_NL);
}

function refusal(text: string | Uint8Array, name: string): string {
  try {
    parsePhotometry(text, name);
  } catch (error) {
    expect(error).toBeInstanceOf(PhotometryParseError);
    const message = (error as Error).message;
    expect(message).not.toMatch(/[\r\n]/);
    expect(message.length).toBeLessThanOrEqual(200);
    return message;
  }
  throw new Error(`${name} was accepted`);
}

function expectFinite(ph: Photometry): void {
  for (const row of ph.candela) for (const cd of row) expect(Number.isFinite(cd) && cd >= 0 && cd <= 1e9).toBe(true);
  const flux = integrateFlux(ph);
  expect(Number.isFinite(flux) && flux <= 1e7).toBe(true);
  if (ph.statedLumens !== null) expect(Number.isFinite(ph.statedLumens)).toBe(true);
}

describe('numerals of absurd length: linear time, short messages', () => {
  const minMs = (f: () => void, reps = 5): number => {
    let best = Infinity;
    for (let r = 0; r < reps; r++) {
      const t0 = performance.now();
      f();
      best = Math.min(best, performance.now() - t0);
    }
    return best;
  };
  const digits = (n: number): string => '1'.repeat(n);
  // Each case builds an input with an n-digit run where issue 18 found a
  // quadratic regular expression (or quadratic string building).
  const CASES: Record<string, (n: number) => [string, string]> = {
    'IES candela value + "x"': (n) => [iso(undefined, undefined, `100 ${digits(n)}x`), 'a.ies'],
    'IES trailing numeral (leftover check)': (n) => [`${ISO}\n${digits(n)}.5e\n`, 'a.ies'],
    'IES [_ABSOLUTELUMENS]': (n) => [ISO.replace('[LUMINAIRE]', `[_ABSOLUTELUMENS] ${digits(n)}\n[LUMINAIRE]`), 'a.ies'],
    'IES [LAMP] "NNN lm"': (n) => [ISO.replace('[LUMINAIRE]', `[LAMP] ${digits(n)} lmx ${digits(n)} lm\n[LUMINAIRE]`), 'a.ies'],
    'IES version line with a run of spaces': (n) => [ISO.replace('IESNA:LM-63-2002', `IESNA${' '.repeat(n)}x`), 'a.ies'],
    'format sniffing over blank lines': (n) => ['\n'.repeat(Math.min(n, 19_000)) + ISO.replace('TILT=NONE', 'TILT =NONE'), 'no-extension'],
    'LDT header line + "x"': (n) => [ldtWith(4, `${digits(n)}x`), 'a.ldt'],
    'LDT angle + "x"': (n) => [ldtWith(43, `${digits(n)}x`), 'a.ldt'],
    'LDT decimal comma line': (n) => [ldtWith(4, `${digits(n)},`), 'a.ldt'],
  };
  for (const [what, make] of Object.entries(CASES)) {
    it(`${what}: 100k → 1M digits grows < 40× (linear, not quadratic)`, () => {
      const [small, name] = make(100_000);
      const [big] = make(1_000_000);
      const parse = (text: string) => () => {
        try {
          const ph = parsePhotometry(text, name);
          expectFinite(ph);
        } catch (error) {
          if (!(error instanceof PhotometryParseError)) throw error;
          expect(error.message.length).toBeLessThanOrEqual(200);
          expect(error.message).not.toContain('1111111111111111111111111111');
        }
      };
      parse(small)(); // warm-up
      const tSmall = minMs(parse(small));
      const tBig = minMs(parse(big), 3);
      // A complexity check, not a speed limit (speed is measured in benchmarks): linear: ×10; the quadratic regexes of issue 18 gave ×100. The margin
      // (and +1 ms on the small run) absorbs timer noise and GC on 2 busy cores.
      expect(tBig / (tSmall + 1)).toBeLessThan(40);
    });
  }

  it('[MORE] continuation lines are joined once: 900 → 9 000 lines grows < 40× (linear)', () => {
    const make = (n: number): string => ISO.replace('[LUMINAIRE] isotropic', `[LUMINAIRE] a\n${'[MORE] ' + 'x'.repeat(100) + '\n'}`.repeat(1) + `[MORE] ${'y'.repeat(100)}\n`.repeat(n));
    let ph = parsePhotometry(make(9_000), 'a.ies'); // warm-up
    const tSmall = minMs(() => parsePhotometry(make(900), 'a.ies'));
    const tBig = minMs(() => (ph = parsePhotometry(make(9_000), 'a.ies')), 3);
    // Joining each line onto a growing string again and again was quadratic (×100 here).
    expect(tBig / (tSmall + 1)).toBeLessThan(40);
    expect(ph.luminaire.length).toBeGreaterThan(9_000 * 100);
  });

  it('a numeral > 100 characters is refused with its length, not quoted', () => {
    expect(refusal(iso(undefined, `${'1'.repeat(100_000)} 1 10`), 'long.ies')).toBe('long.ies line 8: the ballast factor: a numeral of 100000 characters is too long (limit 100)');
    expect(refusal(ldtWith(4, '0.' + '0'.repeat(200)), 'long.ldt')).toBe('long.ldt line 5: the C-plane distance Dc: a numeral of 202 characters is too long (limit 100)');
  });

  it('the decimal scanner: grammar and extremes', () => {
    for (const ok of ['12', '-0.5', '.625', '5000.', '1.2E+03', '+7', '1e-5']) expect(isDecimal(ok)).toBe(true);
    for (const bad of ['', '.', '-', 'e5', '1e', '1e+', '0x1F', 'Infinity', 'NaN', '1..2', '1.2.3', '--1', '1 2']) expect(isDecimal(bad)).toBe(false);
    expect(readDecimal('1e400')).toEqual({ ok: false, problem: 'out of range' });
    expect(readDecimal('-0')).toEqual({ ok: true, value: 0 });
    expect(Object.is((readDecimal('-0') as { value: number }).value, 0)).toBe(true);
    expect(readDecimal('NaN')).toEqual({ ok: false, problem: 'not a number' });
  });
});

describe('maximum input size', () => {
  it(`refuses more than ${MAX_PHOTOMETRY_BYTES / 1048576} MB before parsing, bytes or text`, () => {
    const bytes = new Uint8Array(MAX_PHOTOMETRY_BYTES + 1).fill(0x20);
    expect(refusal(bytes, 'huge.ies')).toBe('huge.ies: the file is 10 MB, over the 10 MB limit for photometric files');
    expect(refusal(' '.repeat(MAX_PHOTOMETRY_BYTES + 1), 'huge.ldt')).toContain('over the 10 MB limit');
  });
});

describe('values are checked after every scaling step', () => {
  const CASES: Record<string, [string, string, string]> = {
    'multiplier 1e308': [iso('1 -1 1e308 19 1 1 2 0 0 0'), 'm.ies', 'm.ies line 7: candela multiplier 1e+308 is out of range (0.000001 to 1000000)'],
    'ballast factor 1e308': [iso(undefined, '1e308 1 10'), 'b.ies', 'b.ies line 8: ballast factor 1e+308 is out of range (0.001 to 10)'],
    'in-range multiplier × in-range candela > 1e9 cd': [
      iso('1 -1 1e6 19 1 1 2 0 0 0', undefined, '100 100 100 100 100 100 100 100 100 100000'),
      'x.ies',
      'x.ies line 12: candela value 100000 × scale 1000000 at horizontal angle 0, vertical angle 90 exceeds 1000000000 cd',
    ],
    'one candela 1e308 (integrated flux would be Infinity)': [
      iso(undefined, undefined, '100 100 100 100 100 100 100 100 100 1e308'),
      'f.ies',
      'f.ies line 12: candela value 1e+308 × scale 1 at horizontal angle 0, vertical angle 90 exceeds 1000000000 cd',
    ],
    'integrated flux over 1e7 lm': [iso('1 -1 1e4 19 1 1 2 0 0 0', undefined, '1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5 1e5'), 'g.ies', 'g.ies: integrated flux 6836000000 lm is out of range (0 to 10000000 lm)'],
    'lumens per lamp 1e308 (stated lumens Infinity)': [iso('1 1e308 1 19 1 1 2 0 0 0'), 'l.ies', 'l.ies line 7: lumens per lamp 1e+308 is out of range (0.001 to 10000000)'],
    'lamps × lumens per lamp over 1e7': [iso('1000 1e6 1 19 1 1 2 0 0 0'), 'n.ies', 'n.ies line 7: stated lumens (lamps × lumens per lamp × ballast factor) 1000000000 is out of range'],
    'lumens per lamp 5e-324': [iso('1 5e-324 1 19 1 1 2 0 0 0'), 's.ies', 's.ies line 7: lumens per lamp 5e-324 is out of range'],
    'a 1e308 ft luminous opening': [iso('1 -1 1 19 1 1 1 1e308 0 0'), 'o.ies', 'o.ies line 7: luminous opening width (m) 3.048e+307 is out of range'],
    'candela "NaN"': [iso(undefined, undefined, '100 NaN'), 'nan.ies', 'nan.ies line 12: expected 19 candela values, found 1: expected a candela value, found "NaN"'],
    'candela "Infinity"': [iso(undefined, undefined, '100 Infinity'), 'inf.ies', 'inf.ies line 12: expected 19 candela values, found 1: expected a candela value, found "Infinity"'],
    'candela 1e400': [iso(undefined, undefined, '100 1e400'), 'e.ies', 'e.ies line 12: expected 19 candela values, found 1: a candela value "1e400" is out of range'],
    'multiplier -0': [iso('1 -1 -0 19 1 1 2 0 0 0'), 'z.ies', 'z.ies line 7: candela multiplier must be positive, found 0'],
    'TILT factor 0 at tilt 0 (zero scale)': [ISO.replace('TILT=NONE', 'TILT=INCLUDE\n1\n2\n0 90\n0 1'), 't.ies', 't.ies line 6: the TILT factor at tilt 0 is 0: every candela value would be 0'],
    'LDT conversion factor 1e308 (was NaN cd)': [ldtWith(23, '1e308'), 'c.ldt', 'c.ldt line 24: intensity conversion factor 1e+308 is out of range (0.000001 to 1000000)'],
    'LDT lamp flux 5e-324 (was a zero scale)': [ldtWith(28, '5e-324'), 'z.ldt', 'z.ldt line 29: lamp flux (set 1, lm) 5e-324 is out of range (0.001 to 10000000)'],
    'LDT lamp flux 1e308': [ldtWith(28, '1e308'), 'y.ldt', 'y.ldt line 29: lamp flux (set 1, lm) 1e+308 is out of range'],
    'LDT LORL 1e308 (stated lumens Infinity)': [ldtWith(22, '1e308'), 'r.ldt', 'r.ldt line 23: light output ratio LORL (%) 1e+308 is out of range (0 to 1000)'],
    'LDT luminaire length 1e308 mm': [ldtWith(12, '1e308'), 'd.ldt', 'd.ldt line 13: the luminaire length (mm) 1e+308 is out of range'],
  };
  for (const [what, [text, name, message]] of Object.entries(CASES)) {
    it(`${what} → "${message}"`, () => {
      expect(refusal(text, name).startsWith(message)).toBe(true);
    });
  }

  it('in-range extremes are accepted and stay finite (multiplier 1e-6, candela -0, subnormal candela)', () => {
    const a = parsePhotometry(iso('1 -1 1e-6 19 1 1 2 0 0 0'), 'a.ies');
    expect(intensity(a, 0, 0)).toBeCloseTo(1e-4, 12);
    const b = parsePhotometry(iso(undefined, undefined, '-0 5e-324 100 100 100 100 100 100 100 100'), 'b.ies');
    expect(Object.is(b.candela[0][0], 0)).toBe(true);
    expectFinite(b);
  });

  it('[_ABSOLUTELUMENS] or [LAMP] lumens out of range are ignored with a warning, not stated as Infinity', () => {
    const ph = parsePhotometry(ISO.replace('[LUMINAIRE]', `[_ABSOLUTELUMENS] ${'9'.repeat(400)}\n[LUMINAIRE]`), 'a.ies');
    expect(ph.statedLumens).toBeNull();
    expect(ph.warnings).toContain('[_ABSOLUTELUMENS] states Infinity lm, out of range (0.001 to 10000000 lm); ignored');
    const lamp = parsePhotometry(ISO.replace('[LUMINAIRE]', `[LAMP] LED ${'9'.repeat(400)} lm\n[LUMINAIRE]`), 'b.ies');
    expect(lamp.statedLumens).toBeNull();
    expect(lamp.warnings).toContain('[LAMP] text states Infinity lm, out of range (0.001 to 10000000 lm); ignored');
    expect(parsePhotometry(ISO.replace('[LUMINAIRE]', '[LAMP] LED 1257 lm, 12 W\n[LUMINAIRE]'), 'c.ies').statedLumens).toBe(1257);
  });
});

describe('EULUMDAT is line-based: empty optional lines are "not given"', () => {
  it('a real file with its ten direct ratios, CCT and CRI lines empty reads like the original', () => {
    const blank = loadFixture('ldt_empty_optional_lines.ldt');
    const original = loadReal('zumtobel_arcos3_spot_isym1.ldt');
    expect(blank.candela).toEqual(original.candela);
    expect(blank.horizontalAngles).toEqual(original.horizontalAngles);
    expect(blank.verticalAngles).toEqual(original.verticalAngles);
    expect(blank.statedLumens).toBe(758);
    expect(blank.warnings).toEqual([]);
    expect(integrateFlux(blank) / 758).toBeCloseTo(1.0019, 3);
  });

  it('other optional numeric header lines may be empty too (Dc, Dg, dimensions, DFF, tilt, wattage)', () => {
    const lines = LDT.split(LDT_NL);
    for (const i of [4, 6, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 24, 26, 31]) lines[i] = '';
    const ph = parsePhotometry(lines.join(LDT_NL), 'sparse.ldt');
    expect(ph.candela).toEqual(loadReal('zumtobel_arcos3_spot_isym1.ldt').candela);
    expect(ph.inputWatts).toBeNull();
  });

  it('an empty LORL or conversion factor is said in a warning', () => {
    const noLorl = parsePhotometry(ldtWith(22, ''), 'l.ldt');
    expect(noLorl.statedLumens).toBeNull();
    expect(noLorl.warnings).toEqual(['line 23: the light output ratio LORL is not given; no stated lumens']);
    const noCfli = parsePhotometry(ldtWith(23, ''), 'c.ldt');
    expect(noCfli.warnings).toEqual(['line 24: the intensity conversion factor is not given; 1 is used']);
  });

  it('a required line left empty, or a real count mismatch, names the line and what was expected', () => {
    expect(refusal(ldtWith(3, ''), 'mc.ldt')).toBe('mc.ldt line 4: expected the number of C-planes Mc (a number), found ""');
    expect(refusal(ldtWith(28, ''), 'flux.ldt')).toBe('flux.ldt line 29: expected the lamp flux (set 1) (a number), found ""');
    // One direct-ratio line deleted: the first C angle becomes ratio 10 and the C list runs into the γ list.
    const lines = LDT.split(LDT_NL);
    lines.splice(32, 1);
    expect(refusal(lines.join(LDT_NL), 'dr.ldt')).toBe('dr.ldt line 66: expected 24 C-plane angles, found 23 before 0, which does not ascend after 345 (the count in the header does not match the data, or the angles are out of order)');
    expect(refusal(ldtWith(35, 'abc'), 'txt.ldt')).toBe('txt.ldt line 36: expected direct ratio 4 of 10 (a number or an empty line), found "abc"');
  });

  it('ten direct ratios written on one line are tolerated', () => {
    const lines = LDT.split(LDT_NL);
    const ratios = lines.slice(32, 42).join(' ');
    lines.splice(32, 10, ratios);
    expect(parsePhotometry(lines.join(LDT_NL), 'one.ldt').candela).toEqual(loadReal('zumtobel_arcos3_spot_isym1.ldt').candela);
  });
});
