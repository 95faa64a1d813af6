import { createContext } from 'react';
import type { I18nValue } from './createI18n';
import { ENGLISH } from './english';

/** English with 'en' formatting when no I18nProvider is above (unit tests that render one component); mountLuxbox always provides the configured language. */
export const I18nContext = createContext<I18nValue>(ENGLISH);
