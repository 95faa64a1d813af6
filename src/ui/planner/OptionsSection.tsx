import './registerOptionsEnglish';
import type { ReactNode } from 'react';
import { useI18n } from '../i18n/useI18n';

/** The options panel's frame: the selection's title, a close button, and its settings. */
export function OptionsSection({ title, onClose, children }: { title: string; onClose: () => void; children: ReactNode }) {
  const { t } = useI18n();
  return (
    <section className="panel-section options-panel" aria-label={t('options.panel')} data-testid="options-panel">
      <div style={{ display: 'flex', alignItems: 'center', gap: 8 }}>
        <h2 style={{ flex: 1, margin: 0 }}>{title}</h2>
        <button type="button" className="btn" onClick={onClose} aria-label={t('options.close')}>
          ✕
        </button>
      </div>
      {children}
    </section>
  );
}
