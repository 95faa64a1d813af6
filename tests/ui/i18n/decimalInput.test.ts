import { describe, expect, it } from 'vitest';
import { decimalFieldFormat, parseDecimal } from '../../../src/ui/i18n/decimalInput';
import { createFormat } from '../../../src/ui/i18n/createFormat';

describe('parseDecimal: what people type into a number field, in any of the four languages', () => {
  it('takes both decimal marks', () => {
    expect(parseDecimal('2,8')).toBe(2.8);
    expect(parseDecimal('2.8')).toBe(2.8);
    expect(parseDecimal(' 2,80 ')).toBe(2.8);
    expect(parseDecimal('0,05')).toBe(0.05);
    expect(parseDecimal(',5')).toBe(0.5);
    expect(parseDecimal('3,')).toBe(3);
    expect(parseDecimal('45')).toBe(45);
  });

  it('a single mark is always the decimal one (metres, degrees, seconds: a thousand is never meant)', () => {
    expect(parseDecimal('1.234')).toBe(1.234);
    expect(parseDecimal('1,234')).toBe(1.234);
  });

  it('grouping as the locales write it: German, French (narrow no-break space), Swiss (apostrophe), English', () => {
    expect(parseDecimal('1.234,5')).toBe(1234.5);
    expect(parseDecimal('1\u202f234,5')).toBe(1234.5);
    expect(parseDecimal('1\u00a0234,5')).toBe(1234.5);
    expect(parseDecimal('1’234.5')).toBe(1234.5);
    expect(parseDecimal("1'234.5")).toBe(1234.5);
    expect(parseDecimal('1,234.5')).toBe(1234.5);
    expect(parseDecimal('1.234.567')).toBe(1234567);
    expect(parseDecimal('1.234.567,25')).toBe(1234567.25);
  });

  it('signs: hyphen-minus, the typographic minus, plus', () => {
    expect(parseDecimal('-45')).toBe(-45);
    expect(parseDecimal('−2,5')).toBe(-2.5);
    expect(parseDecimal('+2,5')).toBe(2.5);
  });

  it('anything else is not a number (NaN), not a guess', () => {
    for (const bad of ['', '  ', 'abc', '2,8m', '1,2,3', '1.23.4', '12.34,5', '1,2.3,4', '2..8', '--2', '1e3', '0x10', '.', ',', '1.234,5.6', '1,23.4']) expect(parseDecimal(bad), bad).toBeNaN();
  });

  it('round-trips every value a field shows, in every locale the configurator formats for', () => {
    for (const locale of ['en', 'de', 'de-CH', 'de-AT', 'fr', 'fr-CH', 'it', 'it-CH', 'en-US', 'de-US']) {
      const format = createFormat(locale);
      for (const x of [0, 0.05, 1.5, 2.8, 12.75, 29.999, -3.25, 1234.5]) {
        for (const d of [0, 1, 2, 3]) {
          const shown = format.number(x, decimalFieldFormat(d));
          expect(parseDecimal(shown), `${locale} ${x} ${d}: ${shown}`).toBeCloseTo(Number(x.toFixed(d)), 9);
        }
      }
    }
  });

  it('shows the decimal comma in German, French and Italian, the point in English and Swiss German', () => {
    const shown = (locale: string) => createFormat(locale).number(2.8, decimalFieldFormat({ max: 3 }));
    expect(['de', 'fr', 'it', 'de-DE', 'fr-FR', 'it-IT'].map(shown)).toEqual(Array(6).fill('2,8'));
    expect(shown('en')).toBe('2.8');
    expect(shown('de-CH')).toBe('2.8');
    expect(createFormat('de').number(1234.5, decimalFieldFormat(2))).toBe('1234,50');
  });
});
