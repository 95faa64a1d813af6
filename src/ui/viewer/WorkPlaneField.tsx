import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';

export interface WorkPlane {
  on: boolean;
  /** Metres above the floor. */
  height: number;
}

/** The work plane's switch and height; a height outside 0.1 m … `maxHeight` goes to the nearest one allowed. */
export function WorkPlaneField({ plane, maxHeight, onChange }: { plane: WorkPlane; maxHeight: number; onChange: (plane: WorkPlane) => void }) {
  const { t } = useI18n();
  return (
    <label className="viewer3d-field viewer3d-inline">
      <input type="checkbox" checked={plane.on} onChange={(e) => onChange({ ...plane, on: e.target.checked })} data-testid="plane-on" /> {t('view3d.workPlaneAt')}
      {/* In the locale's format ("0,75" in German), committed on Enter or blur. */}
      <CommitField label={t('view3d.workPlaneHeight')} value={plane.height} onCommit={(h) => (onChange({ ...plane, height: Math.min(maxHeight, Math.max(0.1, h)) }), null)} onRefused={() => undefined} testId="plane-height" /> m
    </label>
  );
}
