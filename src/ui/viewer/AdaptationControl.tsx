import './registerView3dEnglish';
import { useState } from 'react';
import type { AdaptationSetting } from '../../engines/view/adaptationSetting';
import { useI18n } from '../i18n/useI18n';

/** What the control drives: the viewer controller's setAdaptation (createViewerController). */
export interface AdaptationTarget {
  setAdaptation(setting: AdaptationSetting): void;
}

interface Props {
  /** Where the view starts (embed option `adapt`, `?adapt=`); applied by the host when it creates the controller. */
  initial: AdaptationSetting;
  target: () => AdaptationTarget | null;
}

/** The white-balance slider's range (K): candle-warm to daylight; the CLI and embed option take 1000..20000. */
const CCT_SLIDER_MIN = 2000;
const CCT_SLIDER_MAX = 6500;
/** Camera white balance starts at the warm white most interiors use. */
const DEFAULT_CAMERA_CCT = 3000;

const KINDS = ['eye', 'camera', 'none'] as const;
const LABEL = { eye: 'exposure.adaptEye', camera: 'exposure.adaptCamera', none: 'exposure.adaptNone' } as const;
const HINT = { eye: 'exposure.adaptEyeHint', camera: 'exposure.adaptCameraHint', none: 'exposure.adaptNoneHint' } as const;

/**
 * Chromatic adaptation of the 3D view (docs/viewer.md, "Adaptation"): Eye (default, CAT16 with
 * CAM16's degree of adaptation to the lamps' mixed white), Camera (white balance at a CCT), None
 * (the physical colour).
 */
export function AdaptationControl({ initial, target }: Props) {
  const { t } = useI18n();
  const [setting, setSetting] = useState<AdaptationSetting>(initial);
  const [cct, setCct] = useState(initial.kind === 'camera' ? initial.cct : DEFAULT_CAMERA_CCT);
  const choose = (next: AdaptationSetting) => {
    setSetting(next);
    target()?.setAdaptation(next);
  };
  return (
    <div className="viewer3d-group" role="group" aria-label={t('exposure.adaptation')} data-testid="adaptation-control" data-adapt={setting.kind === 'camera' ? `camera:${setting.cct}` : setting.kind}>
      <span className="viewer3d-group-label">{t('exposure.adaptation')}</span>
      {KINDS.map((kind) => (
        <button
          key={kind}
          type="button"
          className={`btn${setting.kind === kind ? ' btn-primary' : ''}`}
          aria-pressed={setting.kind === kind}
          title={t(HINT[kind])}
          onClick={() => choose(kind === 'camera' ? { kind, cct } : { kind })}
          data-testid={`adapt-${kind}`}
        >
          {t(LABEL[kind])}
        </button>
      ))}
      {setting.kind === 'camera' && (
        <label className="viewer3d-field">
          {t('exposure.whiteBalance', { cct: String(cct) })}
          <input
            type="range"
            min={Math.min(CCT_SLIDER_MIN, cct)}
            max={Math.max(CCT_SLIDER_MAX, cct)}
            step={100}
            value={cct}
            onChange={(e) => {
              const v = Number(e.target.value);
              setCct(v);
              choose({ kind: 'camera', cct: v });
            }}
            data-testid="adapt-cct"
          />
        </label>
      )}
    </div>
  );
}
