import { QUALITY_LEVEL_NAMES, type QualityLevel } from '../../engines/relight/qualityLevels';
import type { MessageKey } from '../i18n/messageTypes';
import { useI18n } from '../i18n/useI18n';

const QUALITY_LABEL: Record<QualityLevel, MessageKey> = { fast: 'view3d.qualityFast', balanced: 'view3d.qualityBalanced', best: 'view3d.qualityBest' };

/** The bake's quality level (fast, balanced, best); the one the service runs at is pressed. */
export function QualityButtons({ quality, onChoose }: { quality: QualityLevel; onChoose: (level: QualityLevel) => void }) {
  const { t } = useI18n();
  return (
    <div className="viewer3d-group" role="group" aria-label={t('view3d.quality')}>
      <span className="viewer3d-group-label">{t('view3d.qualityLabel')}</span>
      {QUALITY_LEVEL_NAMES.map((q) => (
        <button key={q} type="button" className={`btn${quality === q ? ' btn-primary' : ''}`} aria-pressed={quality === q} onClick={() => onChoose(q)} data-testid={`quality-${q}`}>
          {t(QUALITY_LABEL[q])}
        </button>
      ))}
    </div>
  );
}
