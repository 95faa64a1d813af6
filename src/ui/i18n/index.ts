// The UI's language layer (docs/i18n.md).
export { useI18n } from './useI18n';
export { I18nProvider } from './I18nProvider';
export { LanguageSwitch } from './LanguageSwitch';
export { createI18n, type I18n, type I18nValue, type I18nOptions } from './createI18n';
export { createFormat, type Format } from './createFormat';
export { isMessageKey } from './createTranslator';
export { resolveLocale, localeForLanguage, preferLanguage, isLocaleTag, type ResolvedLocale } from './resolveLocale';
export { LANGUAGES, LANGUAGE_ENDONYMS, isLanguage, type Language } from './languages';
export type { MessageKey, MessageParams, Translate, PluralMessage, AreaMessages, MessageTree } from './messageTypes';
export { translateCoded, type CodedMessage } from './translateCoded';
