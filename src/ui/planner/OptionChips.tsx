import type { ReactNode } from 'react';

/** A titled row of touch-sized choices in the options panel. */
export function OptionChips({ title, children }: { title: string; children: ReactNode }) {
  return (
    <div className="field" role="group" aria-label={title}>
      <h3>{title}</h3>
      <div className="chip-row" style={{ flexWrap: 'wrap' }}>
        {children}
      </div>
    </div>
  );
}
