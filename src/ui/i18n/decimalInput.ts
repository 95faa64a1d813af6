/**
 * Numbers typed into fields, in every language (docs/i18n.md, "Decimal input"). A field shows its
 * value in the UI locale ("2,8" in German, French and Italian; "2.8" in English and in Swiss
 * German, whose decimal mark is a point) without grouping, and takes back what people type in any
 * of them: "2,8" and "2.8" alike, with or without the grouping the locales write ("1.234,5",
 * "1 234,5", "1’234.5", "1,234.5").
 */

/** Spaces of every width and the apostrophes Swiss locales group with: never part of a number. */
const GROUPING_MARKS = /[\s\u00a0\u202f\u2009'’]/g;

/**
 * The number in `text`, or NaN when it is none (empty text included).
 *
 * Which mark is the decimal one:
 * - both '.' and ',' present: the last of them ("1.234,5" and "1,234.5" are 1234.5), and the other
 *   one must group digits in threes;
 * - one kind, written twice or more ("1.234.567"): grouping;
 * - one kind, written once: the decimal mark, whichever it is ("2,8" = "2.8" = 2.8; "1.234" = 1.234).
 *   The fields take metres, degrees, seconds and scale factors, where a thousand is never meant and
 *   a typed decimal point on a German keyboard is common; reading "1.234" as 1234 would silently
 *   turn 1.234 m into 1.2 km.
 * A leading minus may be '-' or the typographic '−' (U+2212).
 */
export function parseDecimal(text: string): number {
  let s = text.replace(GROUPING_MARKS, '').replace(/^[−–]/, '-');
  if (s === '' || !/^[-+]?[\d.,]+$/.test(s)) return NaN;
  const lastDot = s.lastIndexOf('.');
  const lastComma = s.lastIndexOf(',');
  if (lastDot >= 0 && lastComma >= 0) {
    const decimal = lastDot > lastComma ? '.' : ',';
    const group = decimal === '.' ? ',' : '.';
    const [whole, fraction, ...rest] = s.split(decimal);
    if (rest.length > 0 || fraction.includes(group) || !groupedInThrees(whole, group)) return NaN;
    s = `${whole.split(group).join('')}.${fraction}`;
  } else {
    const mark = lastDot >= 0 ? '.' : lastComma >= 0 ? ',' : null;
    if (mark) {
      const parts = s.split(mark);
      if (parts.length > 2) {
        if (!groupedInThrees(s, mark)) return NaN;
        s = parts.join('');
      } else s = parts.join('.');
    }
  }
  if (!/^[-+]?(\d+\.?\d*|\.\d+)$/.test(s)) return NaN;
  return Number(s);
}

/** "1.234.567" grouped by '.': a first group of 1–3 digits (after a sign), then groups of exactly three. */
function groupedInThrees(s: string, group: string): boolean {
  const [first, ...others] = s.replace(/^[-+]/, '').split(group);
  return /^\d{1,3}$/.test(first) && others.every((g) => /^\d{3}$/.test(g));
}

/** Intl's options for a field's value: the locale's decimal mark, no grouping, `decimals` fraction digits (or up to `maxDecimals`). */
export function decimalFieldFormat(decimals: number | { max: number }): Intl.NumberFormatOptions {
  return typeof decimals === 'number' ? { useGrouping: false, minimumFractionDigits: decimals, maximumFractionDigits: decimals } : { useGrouping: false, maximumFractionDigits: decimals.max };
}
