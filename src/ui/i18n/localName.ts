import type { Language } from './languages';

/** A catalog entry's optional translations (docs/catalog-format.md, "Translations"). */
export interface Translatable {
  readonly name: string;
  readonly names?: Partial<Record<Language, string>>;
  readonly description?: string;
  readonly descriptions?: Partial<Record<Language, string>>;
}

/** The entry's name in `language` when the catalog has one, else its own (source) name. */
export function localName(item: Translatable, language: Language): string {
  return item.names?.[language] || item.name;
}

/** The entry's description in `language` when the catalog has one, else its own. */
export function localDescription(item: Translatable, language: Language): string {
  return item.descriptions?.[language] || (item.description ?? '');
}

/** A catalog beam's label in `language` (`labels`), else its own. */
export function localLabel(item: { readonly label: string; readonly labels?: Partial<Record<Language, string>> }, language: Language): string {
  return item.labels?.[language] || item.label;
}
