import { createContext } from 'react';
import { createI18n, type I18nValue } from './createI18n';

/**
 * English with 'en' formatting when no I18nProvider is above (unit tests that render one
 * component); mountLuxbox always provides the configured language.
 */
export const I18nContext = createContext<I18nValue>(createI18n({ locale: 'en' }).getSnapshot());
