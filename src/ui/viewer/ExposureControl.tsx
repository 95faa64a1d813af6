import './registerView3dEnglish';
import { useState } from 'react';
import { EV100_MAX, EV100_MIN, type ExposureSetting } from '../../engines/view/photographicExposure';
import { useI18n } from '../i18n/useI18n';

/** What the control drives: the viewer controller's exposure methods (createViewerController). */
export interface ExposureTarget {
  setExposureEv(ev: number): void;
  setEv100(ev100: number | null): void;
  currentEv100(): number;
  /** Adapt the automatic exposure to the light on screen now (it holds while the light is only dimmed or recoloured). */
  reAdapt(): void;
}

interface Props {
  /** Where the view starts; a number is applied by the host when it creates the controller. */
  initial: ExposureSetting;
  /** The running controller, or null before the view has one. */
  target: () => ExposureTarget | null;
}

/** The slider's range for a fixed EV100: rooms lie around EV100 3–10; the CLI and the embed option take −6..20. */
const SLIDER_MIN = -2;
const SLIDER_MAX = 16;

/**
 * Exposure of the 3D view (docs/viewer.md, "Exposure"): automatic with a
 * compensation in stops (adapting like an eye and held while the light is only dimmed or
 * recoloured; "Re-adapt" adapts it to the light on screen), or locked. "Lock exposure" keeps the EV100 on screen
 * now, so comparing configurations or dimming keeps it and a dimmer room looks
 * darker; the EV100 slider then sets it (photographicExposure.ts).
 */
export function ExposureControl({ initial, target }: Props) {
  const { t, format } = useI18n();
  const [compensation, setCompensation] = useState(0);
  const [ev100, setEv100] = useState<number | null>(typeof initial === 'number' ? initial : null);
  const ev = (x: number, signed: boolean) => `${signed && x > 0 ? '+' : ''}${format.number(x, { minimumFractionDigits: 1, maximumFractionDigits: 1 })}`;
  const fix = (value: number | null) => {
    setEv100(value);
    target()?.setEv100(value);
  };
  const lock = () => {
    const current = target()?.currentEv100();
    if (current !== undefined && Number.isFinite(current)) fix(Math.min(EV100_MAX, Math.max(EV100_MIN, current)));
  };
  return (
    <div className="viewer3d-group" role="group" aria-label={t('exposure.group')} data-testid="exposure-control" data-ev100={ev100 ?? 'auto'}>
      <span className="viewer3d-group-label">{t('exposure.group')}</span>
      <button type="button" className={`btn${ev100 === null ? ' btn-primary' : ''}`} aria-pressed={ev100 === null} onClick={() => fix(null)} data-testid="exposure-auto">
        {t('exposure.auto')}
      </button>
      <button type="button" className={`btn${ev100 !== null ? ' btn-primary' : ''}`} aria-pressed={ev100 !== null} title={t('exposure.lockHint')} onClick={lock} data-testid="exposure-lock">
        {t('exposure.lock')}
      </button>
      {ev100 === null ? (
        <>
          <label className="viewer3d-field">
            {t('exposure.compensation', { ev: ev(compensation, true) })}
            <input
              type="range"
              min={-4}
              max={4}
              step={0.5}
              value={compensation}
              onChange={(e) => {
                const v = Number(e.target.value);
                setCompensation(v);
                target()?.setExposureEv(v);
              }}
              data-testid="exposure"
            />
          </label>
          <button
            type="button"
            className="btn"
            disabled={compensation === 0}
            onClick={() => {
              setCompensation(0);
              target()?.setExposureEv(0);
            }}
          >
            {t('exposure.resetCompensation')}
          </button>
          <button type="button" className="btn" title={t('exposure.reAdaptHint')} onClick={() => target()?.reAdapt()} data-testid="exposure-readapt">
            {t('exposure.reAdapt')}
          </button>
        </>
      ) : (
        <label className="viewer3d-field">
          {t('exposure.ev100', { ev: ev(ev100, false) })}
          <input
            type="range"
            min={Math.min(SLIDER_MIN, Math.floor(ev100))}
            max={Math.max(SLIDER_MAX, Math.ceil(ev100))}
            step={0.1}
            value={ev100}
            aria-label={t('exposure.ev100Field')}
            onChange={(e) => fix(Number(e.target.value))}
            data-testid="exposure-ev100"
          />
        </label>
      )}
    </div>
  );
}
