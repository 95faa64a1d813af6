import { useContext } from 'react';
import type { I18nValue } from './createI18n';
import { I18nContext } from './i18nContext';

/** `const { t, format, language, locale, setLanguage } = useI18n()` in every component that shows text (docs/i18n.md). */
export function useI18n(): I18nValue {
  return useContext(I18nContext);
}
