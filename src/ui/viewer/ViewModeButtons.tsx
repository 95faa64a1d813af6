import type { ViewMode } from '../../engines/view/roomView';
import { useI18n } from '../i18n/useI18n';

export interface ViewModeButtonsProps {
  mode: ViewMode;
  glare: boolean;
  onMode: (mode: ViewMode) => void;
  onGlare: (on: boolean) => void;
}

/** Light or lux (false colour) mode, and the veiling glare switch (docs/viewer.md, "Glare"). */
export function ViewModeButtons({ mode, glare, onMode, onGlare }: ViewModeButtonsProps) {
  const { t } = useI18n();
  return (
    <div className="viewer3d-group" role="group" aria-label={t('view3d.viewMode')}>
      <button type="button" className={`btn${mode === 'light' ? ' btn-primary' : ''}`} aria-pressed={mode === 'light'} onClick={() => onMode('light')}>
        {t('view3d.modeLight')}
      </button>
      <button type="button" className={`btn${mode === 'lux' ? ' btn-primary' : ''}`} aria-pressed={mode === 'lux'} onClick={() => onMode('lux')} data-testid="mode-lux">
        {t('view3d.modeLux')}
      </button>
      <button type="button" className={`btn${glare ? ' btn-primary' : ''}`} aria-pressed={glare} title={t('view3d.glareHint')} onClick={() => onGlare(!glare)} data-testid="glare-toggle">
        {t('view3d.glare')}
      </button>
    </div>
  );
}
