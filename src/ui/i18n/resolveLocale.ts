import { SOURCE_LANGUAGE, isLanguage, type Language } from './languages';

/** What a requested locale resolves to: the UI language, and the full tag numbers and prices are formatted for. */
export interface ResolvedLocale {
  language: Language;
  /** A BCP 47 tag Intl accepts, e.g. 'de-CH' (German texts, Swiss number formatting). */
  locale: string;
}

/** The canonical form of a tag ('DE-ch' → 'de-CH'), or null when Intl does not accept it. */
function canonical(tag: string): string | null {
  try {
    return Intl.getCanonicalLocales(tag.trim())[0] ?? null;
  } catch {
    return null;
  }
}

/**
 * Resolves a BCP 47 tag or a preference list (navigator.languages) to a UI language and a
 * formatting locale: the first tag whose primary subtag is a supported language wins, and its
 * full tag becomes the formatting locale ('de-CH' → German texts, "1’234.50" numbers; the
 * currency stays the catalog's). Tags Intl rejects are skipped; nothing supported → English,
 * formatted for the first valid tag asked for (an 'es-ES' shopper reads English texts with
 * Spanish number formatting) or plain 'en'.
 */
export function resolveLocale(requested: string | readonly string[] | null | undefined): ResolvedLocale {
  const list = requested == null ? [] : typeof requested === 'string' ? [requested] : requested;
  const valid = list.map((t) => (typeof t === 'string' ? canonical(t) : null)).filter((t): t is string => t !== null);
  for (const tag of valid) {
    const primary = tag.split('-')[0].toLowerCase();
    if (isLanguage(primary)) return { language: primary, locale: tag };
  }
  return { language: SOURCE_LANGUAGE, locale: valid[0] ?? SOURCE_LANGUAGE };
}

/**
 * The formatting locale after the user switches to `language`: the region of the current locale
 * is kept ('de-CH' switched to French → 'fr-CH', still Swiss formatting); without a region the
 * language alone.
 */
export function localeForLanguage(language: Language, current: string): string {
  try {
    const region = new Intl.Locale(current).region;
    if (region) return canonical(`${language}-${region}`) ?? language;
  } catch {
    // an unparsable current locale has no region to keep
  }
  return language;
}

/**
 * The tag to use when the user picked `language` explicitly (`?lang=de`, a stored choice): the
 * browser's own tag for that language when it has one, so the region's formatting survives
 * ('de' with navigator.languages ['de-CH', 'en'] → 'de-CH'), else the language alone.
 */
export function preferLanguage(language: Language, browserTags: readonly string[] | null | undefined): string {
  for (const tag of browserTags ?? []) {
    const c = typeof tag === 'string' ? canonical(tag) : null;
    if (c && c.split('-')[0].toLowerCase() === language) return c;
  }
  return language;
}

/** Whether Intl accepts `tag` as a BCP 47 language tag. */
export function isLocaleTag(tag: string): boolean {
  return canonical(tag) !== null;
}
