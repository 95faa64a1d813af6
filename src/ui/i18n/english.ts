import { createI18n, type I18nValue } from './createI18n';

/**
 * English with 'en' formatting, for code outside a provider: the default of useI18n() and of
 * helpers that take an optional `t` (their English output stays what tests and logs expect).
 */
export const ENGLISH: I18nValue = createI18n({ locale: 'en' }).getSnapshot();
