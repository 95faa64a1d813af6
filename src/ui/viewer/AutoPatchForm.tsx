import { useState } from 'react';
import { DMX_CHANNELS, DMX_UNIVERSE_MAX, DMX_UNIVERSE_MIN } from '../../core/model/modules/dmxPatch';
import { useI18n } from '../i18n/useI18n';
import './registerView3dEnglish';

export interface AutoPatchParams {
  universe: number;
  address: number;
  resolution: 8 | 16;
  cct: boolean;
}

/** Auto-patch: every module in module order from a start address (one undoable action); clear the patch. */
export function AutoPatchForm({ onAutoPatch, onClear, canClear }: { onAutoPatch(p: AutoPatchParams): string | null; onClear(): void; canClear: boolean }) {
  const { t } = useI18n();
  const [universe, setUniverse] = useState('1');
  const [address, setAddress] = useState('1');
  const [wide, setWide] = useState(false);
  const [cct, setCct] = useState(true);
  const [reason, setReason] = useState<string | null>(null);
  const u = Number(universe);
  const a = Number(address);
  const valid = Number.isInteger(u) && u >= DMX_UNIVERSE_MIN && u <= DMX_UNIVERSE_MAX && Number.isInteger(a) && a >= 1 && a <= DMX_CHANNELS;
  return (
    <div className="viewer3d-autopatch" role="group" aria-label={t('live.autoPatch')}>
      <p className="viewer3d-dim">{t('live.autoPatchIntro')}</p>
      <div className="viewer3d-patch-fields">
        <label className="viewer3d-patch-num">
          {t('live.universeShort')}
          <input
            type="number"
            min={DMX_UNIVERSE_MIN}
            max={DMX_UNIVERSE_MAX}
            step={1}
            inputMode="numeric"
            value={universe}
            onChange={(e) => setUniverse(e.target.value)}
            aria-label={t('live.autoPatchUniverse')}
            data-testid="autopatch-universe"
          />
        </label>
        <label className="viewer3d-patch-num">
          @
          <input type="number" min={1} max={DMX_CHANNELS} step={1} inputMode="numeric" value={address} onChange={(e) => setAddress(e.target.value)} aria-label={t('live.autoPatchAddress')} data-testid="autopatch-address" />
        </label>
        <label className="viewer3d-patch-cct">
          <input type="checkbox" checked={wide} onChange={(e) => setWide(e.target.checked)} data-testid="autopatch-16bit" /> {t('live.sixteenBit')}
        </label>
        <label className="viewer3d-patch-cct">
          <input type="checkbox" checked={cct} onChange={(e) => setCct(e.target.checked)} data-testid="autopatch-cct" /> {t('live.cct')}
        </label>
      </div>
      <div className="viewer3d-group">
        <button type="button" className="btn" disabled={!valid} onClick={() => setReason(onAutoPatch({ universe: u, address: a, resolution: wide ? 16 : 8, cct }))} data-testid="autopatch">
          {t('live.autoPatch')}
        </button>
        <button type="button" className="btn" disabled={!canClear} onClick={onClear} data-testid="clear-patch">
          {t('live.clearPatch')}
        </button>
      </div>
      {!valid && <p className="viewer3d-patch-reason">{t('live.patchRange', { umin: DMX_UNIVERSE_MIN, umax: DMX_UNIVERSE_MAX, channels: DMX_CHANNELS })}</p>}
      {reason && (
        <p className="viewer3d-patch-reason" role="alert">
          {reason}
        </p>
      )}
    </div>
  );
}
