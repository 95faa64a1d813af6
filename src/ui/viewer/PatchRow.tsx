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
        <select
          aria-label={t('live.modeOf', { id })}
          value={patch ? String(patch.resolution) : 'off'}
          onChange={(e) => {
            const v = e.target.value;
            if (v === 'off') return attempt(null);
            const resolution = v === '16' ? 16 : 8;
            attempt(patch ? { ...patch, resolution } : { universe: 1, address: 1, resolution, cct: tunable });
          }}
          data-testid={`patch-mode-${id}`}
        >
          <option value="off">{t('live.notPatched')}</option>
          <option value="8">{t('live.eightBit')}</option>
          <option value="16">{t('live.sixteenBit')}</option>
        </select>
        {patch && (
          <>
            <label className="viewer3d-patch-num">
              {t('live.universeShort')}
              <input
                type="number"
                min={1}
                step={1}
                inputMode="numeric"
                value={universe}
                aria-label={t('live.universeOf', { id })}
                onChange={(e) => edit('universe', e.target.value)}
                onBlur={commitNumbers}
                onKeyDown={onKey}
                data-testid={`patch-universe-${id}`}
              />
            </label>
            <label className="viewer3d-patch-num">
              @
              <input
                type="number"
                min={1}
                max={512}
                step={1}
                inputMode="numeric"
                value={address}
                aria-label={t('live.addressOf', { id })}
                onChange={(e) => edit('address', e.target.value)}
                onBlur={commitNumbers}
                onKeyDown={onKey}
                data-testid={`patch-address-${id}`}
              />
            </label>
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
