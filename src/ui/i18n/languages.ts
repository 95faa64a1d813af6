/** The UI languages luxbox ships (issue #13): English is bundled, the others load as lazy chunks. */
export const LANGUAGES = ['en', 'de', 'fr', 'it'] as const;

export type Language = (typeof LANGUAGES)[number];

/** The language every key is written in first; the fallback when nothing else matches. */
export const SOURCE_LANGUAGE: Language = 'en';

export function isLanguage(x: unknown): x is Language {
  return typeof x === 'string' && (LANGUAGES as readonly string[]).includes(x);
}

/**
 * Each language's name in itself (endonym), as a language switch shows it: a German speaker
 * stranded in the Italian UI still finds "Deutsch". Data, not UI text, so never translated.
 */
export const LANGUAGE_ENDONYMS: Record<Language, string> = {
  en: 'English',
  de: 'Deutsch',
  fr: 'Français',
  it: 'Italiano',
};
