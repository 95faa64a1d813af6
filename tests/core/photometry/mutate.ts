/**
 * Seeded mutations of photometric files for the in-CI fuzz test (issue 18):
 * byte flips, inserted separators, deleted/duplicated spans, truncation,
 * numbers replaced by extremes (1e308, 5e-324, -0, NaN, 1e400, a numeral of
 * 100 000 digits …), digit runs glued to a value, and whole lines duplicated,
 * deleted or blanked — the classes that found the bugs of issue 18.
 */

const HUGE_DIGITS = 100_000;

/** Replacements for one number token. Built lazily: some are 100 kB. */
const EXTREMES: (() => string)[] = [
  () => '1e308',
  () => '-1e308',
  () => '1.7976931348623157e308',
  () => '1e400',
  () => '5e-324',
  () => '1e-320',
  () => '-0',
  () => '0',
  () => 'NaN',
  () => 'Infinity',
  () => '-Infinity',
  () => '0x1F',
  () => '1e9',
  () => '1e6',
  () => '9'.repeat(HUGE_DIGITS),
  () => '1'.repeat(HUGE_DIGITS) + 'x',
  () => '0.' + '0'.repeat(HUGE_DIGITS) + '1',
  () => '1' + '0'.repeat(HUGE_DIGITS) + 'e-' + HUGE_DIGITS,
  () => '1.' + '5'.repeat(HUGE_DIGITS) + 'e',
  () => '-'.repeat(50) + '1',
];

const isSpace = (b: number): boolean => b === 0x20 || b === 0x09 || b === 0x0a || b === 0x0d || b === 0x2c;

function splitLinesKeep(bytes: number[]): number[][] {
  const lines: number[][] = [];
  let current: number[] = [];
  for (const b of bytes) {
    current.push(b);
    if (b === 0x0a) {
      lines.push(current);
      current = [];
    }
  }
  if (current.length) lines.push(current);
  return lines;
}

const ascii = (s: string): number[] => Array.from(s, (ch) => ch.charCodeAt(0) & 0xff);

/** One mutated copy of `bytes` with 1–3 edits, deterministic for a given `next`. */
export function mutate(bytes: Uint8Array, next: () => number): Uint8Array {
  let out = Array.from(bytes);
  const pick = (n: number): number => Math.floor(next() * n);
  const edits = 1 + pick(3);
  for (let e = 0; e < edits && out.length > 0; e++) {
    const at = pick(out.length);
    const kind = pick(11);
    if (kind === 0) {
      out[at] = pick(256);
    } else if (kind === 1) {
      out.splice(at, 0, [0x20, 0x0a, 0x2d, 0x2c, 0x2e, 0x30 + pick(10), 0x1a, 0x00, 0x3b, 0x0d][pick(10)]);
    } else if (kind === 2) {
      out.splice(at, 1 + pick(40));
    } else if (kind === 3) {
      const len = 1 + pick(300);
      out.splice(at, 0, ...out.slice(at, at + len));
    } else if (kind === 4) {
      out.length = at;
    } else if (kind === 5 || kind === 6) {
      // Replace the token around `at` by an extreme value.
      let start = at;
      while (start > 0 && !isSpace(out[start - 1])) start--;
      let end = at;
      while (end < out.length && !isSpace(out[end])) end++;
      const replacement = ascii(EXTREMES[pick(EXTREMES.length)]());
      out = [...out.slice(0, start), ...replacement, ...out.slice(end)];
    } else if (kind === 7) {
      // Glue a long digit run onto the token at `at`.
      const run = ascii((pick(2) ? '7' : '0').repeat(pick(2) ? HUGE_DIGITS : 1 + pick(400)));
      out = [...out.slice(0, at), ...run, ...out.slice(at)];
    } else {
      const lines = splitLinesKeep(out);
      const line = pick(lines.length);
      if (kind === 8) lines.splice(line, 0, lines[line].slice());
      else if (kind === 9) lines.splice(line, 1);
      else lines.splice(line, 0, pick(2) ? [0x0a] : [0x0d, 0x0a]);
      out = lines.flat();
    }
  }
  return Uint8Array.from(out);
}
