import { createFormat, type Format } from './createFormat';
import { createTranslator } from './createTranslator';
import { SOURCE_LANGUAGE, type Language } from './languages';
import { loadMessages, loadedMessages } from './loadMessages';
import type { MessageTree, Translate } from './messageTypes';
import { localeForLanguage, resolveLocale } from './resolveLocale';

/** What components get from useI18n(): one immutable value per language/locale. */
export interface I18nValue {
  t: Translate;
  format: Format;
  language: Language;
  /** The BCP 47 tag numbers and prices are formatted for, e.g. 'de-CH'. */
  locale: string;
  /** Switches the UI language (loads its chunk first; the configuration is untouched). */
  setLanguage: (language: Language) => Promise<void>;
}

export interface I18nSnapshot extends I18nValue {
  /** False until the messages of `language` are loaded: nothing is rendered before, so no English flash. */
  ready: boolean;
}

export interface I18nOptions {
  /** A BCP 47 tag or a preference list such as navigator.languages (resolveLocale). */
  locale?: string | readonly string[] | null;
  /** ISO 4217 code of the catalog's prices, used by format.money. */
  currency?: string;
  /** Called after the user switched language (the standalone app stores it). */
  onLanguageChange?: (language: Language) => void;
}

/** The language state of one mounted configurator, outside React so hosts can read and set it. */
export interface I18n {
  getSnapshot(): I18nSnapshot;
  subscribe(listener: () => void): () => void;
  setLanguage(language: Language): Promise<void>;
  /** Resolves once the starting language's messages are loaded (at once for English). */
  ready: Promise<void>;
}

/**
 * Creates the language state for `options.locale`. When the language's chunk is not loaded yet,
 * the snapshot says `ready: false` until it is; a chunk that fails to load leaves English (with
 * the requested locale's formatting) and logs why, so the configurator still opens.
 */
export function createI18n(options: I18nOptions = {}): I18n {
  const listeners = new Set<() => void>();
  const start = resolveLocale(options.locale);
  let request = 0;

  const setLanguage = async (language: Language): Promise<void> => {
    const mine = ++request;
    const locale = localeForLanguage(language, snapshot.locale);
    let tree: MessageTree;
    try {
      tree = await loadMessages(language);
    } catch (e) {
      console.error(`luxbox: the ${language} texts could not be loaded`, e);
      return;
    }
    // A later switch that finished first wins.
    if (mine !== request) return;
    publish(build(language, locale, tree));
    options.onLanguageChange?.(language);
  };

  const build = (language: Language, locale: string, tree: MessageTree | undefined): I18nSnapshot => {
    const format = createFormat(locale, options.currency);
    const messages = tree ?? (loadedMessages(SOURCE_LANGUAGE) as MessageTree);
    return { t: createTranslator(messages, locale, (x) => format.number(x)), format, language, locale, setLanguage, ready: tree !== undefined };
  };

  const publish = (next: I18nSnapshot) => {
    snapshot = next;
    for (const l of [...listeners]) l();
  };

  let snapshot = build(start.language, start.locale, loadedMessages(start.language));
  const ready = snapshot.ready
    ? Promise.resolve()
    : loadMessages(start.language).then(
        (tree) => {
          if (request === 0) publish(build(start.language, start.locale, tree));
        },
        (e) => {
          console.error(`luxbox: the ${start.language} texts could not be loaded; showing English`, e);
          if (request === 0) publish(build(SOURCE_LANGUAGE, start.locale, loadedMessages(SOURCE_LANGUAGE)));
        },
      );

  return {
    getSnapshot: () => snapshot,
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    setLanguage,
    ready,
  };
}
