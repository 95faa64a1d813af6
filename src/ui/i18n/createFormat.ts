/** Locale-aware formatting, one Intl path for every number, price, percentage and date on screen. */
export interface Format {
  /** A number in the locale ("1’234.5" in de-CH); NaN/∞ show as 0 rather than "NaN" in a price table. */
  number(x: number, options?: Intl.NumberFormatOptions): string;
  /** An amount in the catalog's currency (or `currency` when given), e.g. "CHF 1’234.50" in de-CH, "1 234,50 €" in fr-FR. */
  money(amount: number, currency?: string): string;
  /** A fraction as a percentage (0.25 → "25 %" in de, "25%" in en); whole percent unless options say otherwise. */
  percent(fraction: number, options?: Intl.NumberFormatOptions): string;
  /** Metres with `digits` decimals and the unit ("1.50 m", "1,50 m"); units stay metric in every language. */
  metres(x: number, digits?: number): string;
  /** A date (and time, if options ask) in the locale. */
  date(d: Date | number, options?: Intl.DateTimeFormatOptions): string;
}

function finite(x: number): number {
  return Number.isFinite(x) ? x : 0;
}

/**
 * The formatter of one locale and currency. Every price goes through one
 * `Intl.NumberFormat(locale, { style: 'currency', currency })`, always with an explicit locale,
 * so the engines agree (issue #13: WebKitGTK wrote "€ 1627.00" where Chromium wrote "€1,627.00"
 * when the locale was left to each engine). Formatters are cached per options: creating an
 * Intl.NumberFormat costs far more than formatting with one. An unknown currency code falls back
 * to "1234.50 XYZ" instead of throwing inside a render.
 */
export function createFormat(locale: string, currency?: string): Format {
  const numberFormats = new Map<string, Intl.NumberFormat>();
  const nf = (options: Intl.NumberFormatOptions | undefined): Intl.NumberFormat => {
    const key = options ? JSON.stringify(options) : '';
    let f = numberFormats.get(key);
    if (!f) {
      f = new Intl.NumberFormat(locale, options);
      numberFormats.set(key, f);
    }
    return f;
  };
  const dateFormats = new Map<string, Intl.DateTimeFormat>();
  return {
    number: (x, options) => nf(options).format(finite(x)),
    money(amount, code = currency) {
      const value = finite(amount);
      if (!code) return nf({ minimumFractionDigits: 2, maximumFractionDigits: 2 }).format(value);
      try {
        return nf({ style: 'currency', currency: code }).format(value);
      } catch {
        return `${value.toFixed(2)} ${code}`;
      }
    },
    percent: (fraction, options) => nf({ style: 'percent', maximumFractionDigits: 0, ...options }).format(finite(fraction)),
    metres: (x, digits = 2) => `${nf({ minimumFractionDigits: digits, maximumFractionDigits: digits }).format(finite(x))} m`,
    date(d, options) {
      const key = options ? JSON.stringify(options) : '';
      let f = dateFormats.get(key);
      if (!f) {
        f = new Intl.DateTimeFormat(locale, options);
        dateFormats.set(key, f);
      }
      return f.format(d);
    },
  };
}
