/** A GLDF's localised texts as the catalog's name and translations (docs/gldf.md, "Rules"). */
import type { LocaleTexts } from './gldfProduct';

/** Catalog languages and the GLDF Locale languages they take (a region is ignored: 'de-CH' is German). */
const LANGUAGES = ['en', 'de', 'fr', 'it'] as const;

/** The text for a catalog language: the Locale of that language (any region), else undefined. */
function localeFor(texts: LocaleTexts | undefined, language: string): string | undefined {
  return texts?.find((l) => l.text && l.language.toLowerCase().split(/[-_]/)[0] === language)?.text;
}

/** The catalog's name (English, else the GLDF's default language, else the first) and its translations. */
export function names(texts: LocaleTexts, defaultLanguage: string | undefined): { name: string; names?: Partial<Record<(typeof LANGUAGES)[number], string>> } {
  const name = localeFor(texts, 'en') ?? (defaultLanguage ? localeFor(texts, defaultLanguage.toLowerCase().split(/[-_]/)[0]) : undefined) ?? texts.find((l) => l.text)?.text ?? '';
  const out: Partial<Record<(typeof LANGUAGES)[number], string>> = {};
  for (const lang of LANGUAGES) {
    const t = localeFor(texts, lang);
    if (t !== undefined) out[lang] = t;
  }
  return Object.keys(out).length > 0 ? { name, names: out } : { name };
}

export const firstText = (texts: LocaleTexts): string => texts.find((l) => l.text)?.text ?? '';
