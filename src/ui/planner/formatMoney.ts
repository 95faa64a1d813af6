import { createFormat } from '../i18n/createFormat';
import { isLocaleTag } from '../i18n/resolveLocale';

/** An explicit tag for Intl: every engine then formats alike (issue #13: WebKitGTK's default wrote "€ 1627.00"). */
const tag = (locale?: string) => (locale && isLocaleTag(locale) ? locale : 'en');

/**
 * Prices for code outside React (the shop demo), through the same Intl path as the UI's
 * format.money (src/ui/i18n/createFormat.ts): 'de-CH' + 'CHF' -> "CHF 1'234.50"; an unknown
 * currency code falls back to a plain "1234.50 XYZ" instead of throwing.
 */
export function formatMoney(amount: number, currency: string, locale?: string): string {
  return createFormat(tag(locale), currency).money(amount);
}

/** Metres with two decimals in the given locale ("1.50 m" / "1,50 m"), as format.metres. */
export function formatMetres(metres: number, locale?: string): string {
  return createFormat(tag(locale)).metres(metres);
}
