/**
 * Hand-written scanner for the plain decimal numerals photometric files use:
 * "12", "-0.5", ".625", "5000.", "1.2E+03". One left-to-right pass, so a
 * numeral of 100 000 digits costs 100 000 steps (issue 18: the regular
 * expression it replaces, /^[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?$/,
 * backtracked quadratically on long digit runs: 10 s for 100 000 digits).
 * Deliberately not Number() alone: that would accept "0x1F", "Infinity" and
 * "" (as 0), all of which would be silent nonsense here.
 */

/** Longest numeral accepted. Real files write at most ~20 characters per value. */
export const MAX_NUMERAL_LENGTH = 100;

const isDigit = (c: number): boolean => c >= 48 && c <= 57;

/** Whether `text` is a whole decimal numeral (any length; linear time). */
export function isDecimal(text: string): boolean {
  const n = text.length;
  let i = 0;
  if (i < n && (text.charCodeAt(i) === 43 || text.charCodeAt(i) === 45)) i++; // + -
  let mantissaDigits = 0;
  while (i < n && isDigit(text.charCodeAt(i))) {
    i++;
    mantissaDigits++;
  }
  if (i < n && text.charCodeAt(i) === 46) {
    // '.'
    i++;
    while (i < n && isDigit(text.charCodeAt(i))) {
      i++;
      mantissaDigits++;
    }
  }
  if (mantissaDigits === 0) return false;
  if (i < n && (text.charCodeAt(i) === 101 || text.charCodeAt(i) === 69)) {
    // e E
    i++;
    if (i < n && (text.charCodeAt(i) === 43 || text.charCodeAt(i) === 45)) i++;
    let exponentDigits = 0;
    while (i < n && isDigit(text.charCodeAt(i))) {
      i++;
      exponentDigits++;
    }
    if (exponentDigits === 0) return false;
  }
  return i === n;
}

/** Outcome of reading one numeral: its value, or why it is not one. */
export type DecimalResult = { ok: true; value: number } | { ok: false; problem: 'not a number' | 'too long' | 'out of range' };

/**
 * Reads a numeral: not a decimal numeral, longer than MAX_NUMERAL_LENGTH, or
 * beyond the float range (1e400 → Infinity) are each reported, never returned
 * as a value. -0 becomes 0 (a signed zero has no photometric meaning, and
 * 1 / -0 = -Infinity downstream).
 */
export function readDecimal(text: string): DecimalResult {
  if (!isDecimal(text)) return { ok: false, problem: 'not a number' };
  if (text.length > MAX_NUMERAL_LENGTH) return { ok: false, problem: 'too long' };
  const value = Number(text);
  if (!Number.isFinite(value)) return { ok: false, problem: 'out of range' };
  return { ok: true, value: value === 0 ? 0 : value };
}
