import { useRef, useState } from 'react';
import { useI18n } from '../i18n/useI18n';
import { decimalFieldFormat, parseDecimal } from '../i18n/decimalInput';

export interface CommitFieldProps {
  label: string;
  value: number;
  /** Digits shown when not editing. */
  decimals?: number;
  /** Returns null if the value was accepted, else the reason it was refused. */
  onCommit: (value: number) => string | null;
  onRefused: (reason: string) => void;
  testId?: string;
}

/**
 * A numeric field that edits locally and commits on Enter or blur: one undoable action per
 * edit instead of one per keystroke. A refused or unparsable value snaps back to the model's
 * value and the reason is reported, so the field can never show a state the model rejected.
 * Shown in the UI locale ("1,50" in German); "1,5" and "1.5" are both accepted (parseDecimal, docs/i18n.md "Decimal input").
 */
export function CommitField({ label, value, decimals = 2, onCommit, onRefused, testId }: CommitFieldProps) {
  const { t, format } = useI18n();
  const [draft, setDraft] = useState<string | null>(null);
  const cancelled = useRef(false);
  // In the UI's locale ("1,50" in German); typing either separator works, as parsing accepts both.
  const shown = draft ?? format.number(value, decimalFieldFormat(decimals));

  // Committing happens only on blur (Enter blurs), so a value is never committed twice.
  const commit = () => {
    if (draft === null) return;
    if (cancelled.current) {
      cancelled.current = false;
      setDraft(null);
      return;
    }
    setDraft(null);
    const v = parseDecimal(draft);
    if (!Number.isFinite(v)) {
      onRefused(t('common.notANumber', { label, value: draft.trim() }));
      return;
    }
    if (Math.abs(v - value) < 1e-9) return;
    const refused = onCommit(v);
    if (refused) onRefused(refused);
  };

  return (
    <input
      aria-label={label}
      title={label}
      inputMode="decimal"
      autoComplete="off"
      data-testid={testId}
      value={shown}
      onFocus={(e) => e.target.select()}
      onChange={(e) => setDraft(e.target.value)}
      onBlur={commit}
      onKeyDown={(e) => {
        e.stopPropagation();
        if (e.key === 'Enter') (e.target as HTMLInputElement).blur();
        else if (e.key === 'Escape') {
          cancelled.current = true;
          (e.target as HTMLInputElement).blur();
        }
      }}
    />
  );
}
