import { useState } from 'react';
import type { DmxPatch } from '../../core/model/configuration/configuration';
import type { LiveLevel } from '../../engines/view/liveLevels';
import { useI18n } from '../i18n/useI18n';
import './registerView3dEnglish';

export interface PatchRowProps {
  id: string;
  typeName: string;
  tunable: boolean;
  patch: DmxPatch | undefined;
  /** The module's live level while frames arrive for its universe. */
  live: LiveLevel | undefined;
  /** Dispatches setModulePatch; the refusal's reason when refused. */
  onPatch(patch: DmxPatch | null): string | null;
}

/**
 * One module's patch: universe, address, 8/16-bit (or unpatched), CCT channel.
 * Each edit is one undoable action; a refused one (overlap, past 512) shows the
 * reason and the fields fall back to the stored patch.
 */
export function PatchRow({ id, typeName, tunable, patch, live, onPatch }: PatchRowProps) {
  const { t, format } = useI18n();
  const [draft, setDraft] = useState<{ universe: string; address: string } | null>(null);
  const [reason, setReason] = useState<string | null>(null);
  const universe = draft?.universe ?? String(patch?.universe ?? '');
  const address = draft?.address ?? String(patch?.address ?? '');
  const attempt = (next: DmxPatch | null) => {
    const refused = onPatch(next);
    setReason(refused);
    setDraft(null);
  };
  const commitNumbers = () => {
    if (!draft || !patch) return setDraft(null);
    const u = Number(draft.universe);
    const a = Number(draft.address);
    if (draft.universe.trim() === '' || draft.address.trim() === '' || (u === patch.universe && a === patch.address)) return setDraft(null);
    attempt({ ...patch, universe: u, address: a });
  };
  const onKey = (e: React.KeyboardEvent<HTMLInputElement>) => {
    if (e.key === 'Enter') commitNumbers();
    if (e.key === 'Escape') setDraft(null);
  };
  const edit = (key: 'universe' | 'address', value: string) => setDraft({ universe, address, [key]: value });
  return (
    <li className="viewer3d-patch-row" data-testid={`patch-${id}`}>
      <div className="viewer3d-patch-head">
        <span>
          {typeName} <span className="viewer3d-dim">{id}</span>
        </span>
        <span className="viewer3d-live-value" data-testid={`live-${id}`}>
          {live ? `${format.percent(live.dimming)}${live.cct !== null ? ` · ${Math.round(live.cct)} K` : ''}` : patch ? '–' : ''}
        </span>
      </div>
      <div className="viewer3d-patch-fields">
        <PatchModeSelect id={id} patch={patch} tunable={tunable} onPatch={attempt} />
        {patch && (
          <>
            <PatchNumberField label={t('live.universeShort')} ariaLabel={t('live.universeOf', { id })} value={universe} onChange={(v) => edit('universe', v)} onCommit={commitNumbers} onKey={onKey} testId={`patch-universe-${id}`} />
            <PatchNumberField label="@" max={512} ariaLabel={t('live.addressOf', { id })} value={address} onChange={(v) => edit('address', v)} onCommit={commitNumbers} onKey={onKey} testId={`patch-address-${id}`} />
            {tunable && (
              <label className="viewer3d-patch-cct">
                <input type="checkbox" checked={patch.cct} onChange={(e) => attempt({ ...patch, cct: e.target.checked })} aria-label={t('live.cctOf', { id })} /> {t('live.cct')}
              </label>
            )}
          </>
        )}
      </div>
      {reason && (
        <p className="viewer3d-patch-reason" role="alert">
          {reason}
        </p>
      )}
    </li>
  );
}

/** 8-bit, 16-bit or not patched; patching a module starts at universe 1, address 1 (with CCT where it is tunable). */
function PatchModeSelect({ id, patch, tunable, onPatch }: { id: string; patch: DmxPatch | undefined; tunable: boolean; onPatch(next: DmxPatch | null): void }) {
  const { t } = useI18n();
  return (
    <select
      aria-label={t('live.modeOf', { id })}
      value={patch ? String(patch.resolution) : 'off'}
      onChange={(e) => {
        const v = e.target.value;
        if (v === 'off') return onPatch(null);
        const resolution = v === '16' ? 16 : 8;
        onPatch(patch ? { ...patch, resolution } : { universe: 1, address: 1, resolution, cct: tunable });
      }}
      data-testid={`patch-mode-${id}`}
    >
      <option value="off">{t('live.notPatched')}</option>
      <option value="8">{t('live.eightBit')}</option>
      <option value="16">{t('live.sixteenBit')}</option>
    </select>
  );
}

interface PatchNumberFieldProps {
  label: string;
  ariaLabel: string;
  value: string;
  max?: number;
  testId: string;
  onChange(value: string): void;
  onCommit(): void;
  onKey(e: React.KeyboardEvent<HTMLInputElement>): void;
}

/** A universe or address number: edited as a draft, committed on Enter or blur. */
function PatchNumberField({ label, ariaLabel, value, max, testId, onChange, onCommit, onKey }: PatchNumberFieldProps) {
  return (
    <label className="viewer3d-patch-num">
      {label}
      <input type="number" min={1} max={max} step={1} inputMode="numeric" value={value} aria-label={ariaLabel} onChange={(e) => onChange(e.target.value)} onBlur={onCommit} onKeyDown={onKey} data-testid={testId} />
    </label>
  );
}
