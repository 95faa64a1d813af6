/**
 * Prices shown to shoppers, formatted with the platform's Intl for the embedding page's
 * locale and currency (e.g. 'de-CH' + 'CHF' -> "CHF 1’234.50"). An unknown locale or currency
 * code falls back to a plain "1234.50 XYZ" instead of throwing inside a render.
 */
export function formatMoney(amount: number, currency: string, locale?: string): string {
  const value = Number.isFinite(amount) ? amount : 0;
  try {
    return new Intl.NumberFormat(locale, { style: 'currency', currency }).format(value);
  } catch {
    return `${value.toFixed(2)} ${currency}`;
  }
}

/** Metres with two decimals in the given locale ("1.50 m" / "1,50 m"). */
export function formatMetres(metres: number, locale?: string): string {
  const value = Number.isFinite(metres) ? metres : 0;
  try {
    return `${new Intl.NumberFormat(locale, { minimumFractionDigits: 2, maximumFractionDigits: 2 }).format(value)} m`;
  } catch {
    return `${value.toFixed(2)} m`;
  }
}
