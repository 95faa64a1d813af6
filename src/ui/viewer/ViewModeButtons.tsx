import type { ViewMode } from '../../engines/view/roomView';
import { useI18n } from '../i18n/useI18n';

export interface ViewModeButtonsProps {
  mode: ViewMode;
  glare: boolean;
  onMode: (mode: ViewMode) => void;
  onGlare: (on: boolean) => void;
  /** The daylight-factor mode (useDaylightFactorView): absent while the room has no daylight to show. */
  daylightFactor?: { on: boolean; choose(on: boolean): void };
}

/** Light, lux (false colour) or daylight-factor mode, and the veiling glare switch (docs/viewer.md, "Glare"). */
export function ViewModeButtons({ mode, glare, onMode, onGlare, daylightFactor }: ViewModeButtonsProps) {
  const { t } = useI18n();
  const df = daylightFactor?.on ?? false;
  // Light and lux leave the daylight-factor mode; it is a lux mode of its own light and levels.
  const choose = (m: ViewMode) => {
    daylightFactor?.choose(false);
    onMode(m);
  };
  return (
    <div className="viewer3d-group" role="group" aria-label={t('view3d.viewMode')}>
      <button type="button" className={`btn${mode === 'light' && !df ? ' btn-primary' : ''}`} aria-pressed={mode === 'light' && !df} onClick={() => choose('light')}>
        {t('view3d.modeLight')}
      </button>
      <button type="button" className={`btn${mode === 'lux' && !df ? ' btn-primary' : ''}`} aria-pressed={mode === 'lux' && !df} onClick={() => choose('lux')} data-testid="mode-lux">
        {t('view3d.modeLux')}
      </button>
      {daylightFactor && (
        <button
          type="button"
          className={`btn${df ? ' btn-primary' : ''}`}
          aria-pressed={df}
          title={t('view3d.modeDaylightFactorHint')}
          onClick={() => {
            daylightFactor.choose(true);
            onMode('lux');
          }}
          data-testid="mode-daylight-factor"
        >
          {t('view3d.modeDaylightFactor')}
        </button>
      )}
      <button type="button" className={`btn${glare ? ' btn-primary' : ''}`} aria-pressed={glare} title={t('view3d.glareHint')} onClick={() => onGlare(!glare)} data-testid="glare-toggle">
        {t('view3d.glare')}
      </button>
    </div>
  );
}
