/** halfBits / halfValue (halfFloat.ts) against the binary16 definition: exact values, ties to even, overflow, subnormals, and the 2^-11 bound. */
import { describe, expect, it } from 'vitest';
import { halfBits, halfValue } from '../../../src/engines/relight/halfFloat';
import { createRng } from '../../fuzz/mutate';

describe('binary16 conversion', () => {
  it('keeps exactly representable values and known bit patterns (IEEE 754-2008 table values)', () => {
    expect(halfBits(1)).toBe(0x3c00);
    expect(halfBits(-2)).toBe(0xc000);
    expect(halfBits(65504)).toBe(0x7bff);
    expect(halfBits(2 ** -24)).toBe(0x0001);
    expect(halfBits(0.333251953125)).toBe(0x3555);
    expect(halfBits(0)).toBe(0);
  });

  it('rounds ties to even, overflows to ∞ past 65 520, flushes below 2^-25 to 0', () => {
    // 1 + 2^-11 lies halfway between 1 and 1 + 2^-10: the even one (1) wins; 1 + 3·2^-11 rounds up to 1 + 2^-9.
    expect(halfBits(1 + 2 ** -11)).toBe(0x3c00);
    expect(halfBits(1 + 3 * 2 ** -11)).toBe(0x3c02);
    expect(halfBits(65519)).toBe(0x7bff);
    expect(halfBits(65520)).toBe(0x7c00);
    expect(halfBits(2 ** -26)).toBe(0);
    expect(halfValue(halfBits(3 * 2 ** -25))).toBe(2 ** -23);
  });

  it('errs at most 2^-11 of the value over lux-like values, 0.001 to 50 000 (seeded)', () => {
    const random = createRng(16).next;
    let worst = 0;
    for (let i = 0; i < 20000; i++) {
      const v = Math.fround(10 ** (random() * 7.7 - 3));
      worst = Math.max(worst, Math.abs(halfValue(halfBits(v)) - v) / v);
    }
    expect(worst).toBeLessThanOrEqual(2 ** -11);
    expect(worst).toBeGreaterThan(2 ** -12);
  });
});
