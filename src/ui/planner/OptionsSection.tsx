import type { ReactNode } from 'react';

/** The options panel's frame: the selection's title, a close button, and its settings. */
export function OptionsSection({ title, onClose, children }: { title: string; onClose: () => void; children: ReactNode }) {
  return (
    <section className="panel-section options-panel" aria-label="Options" data-testid="options-panel">
      <div style={{ display: 'flex', alignItems: 'center', gap: 8 }}>
        <h2 style={{ flex: 1, margin: 0 }}>{title}</h2>
        <button type="button" className="btn" onClick={onClose} aria-label="Close options">
          ✕
        </button>
      </div>
      {children}
    </section>
  );
}
