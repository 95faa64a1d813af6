import { LANGUAGES, LANGUAGE_ENDONYMS, isLanguage } from './languages';
import { useI18n } from './useI18n';

/**
 * The visible language switch: a native select (keyboard and screen-reader friendly), each
 * language named in itself and marked with its `lang` so a screen reader pronounces it right.
 */
export function LanguageSwitch({ className }: { className?: string }) {
  const { t, language, setLanguage } = useI18n();
  return (
    <span className={className ?? 'language-switch'}>
      <select
        aria-label={t('common.languageLabel')}
        data-testid="language-switch"
        value={language}
        title={t('common.languageLabel')}
        onChange={(e) => {
          if (isLanguage(e.target.value)) void setLanguage(e.target.value);
        }}
      >
        {LANGUAGES.map((l) => (
          <option key={l} value={l} lang={l}>
            {LANGUAGE_ENDONYMS[l]}
          </option>
        ))}
      </select>
    </span>
  );
}
