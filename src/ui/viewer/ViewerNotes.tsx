import type { ViewMode } from '../../engines/view/roomView';
import { useI18n } from '../i18n/useI18n';
import { LuxLegend } from './LuxLegend';
import { viewerErrorText } from './viewerErrorText';
import type { ViewerStatus } from './viewerStatus';

export interface ViewerNotesProps {
  progress: { fraction: number; done: boolean; lit: boolean };
  error: string | null;
  /** The WebGL context is lost (until restored). */
  lost: boolean;
  mode: ViewMode;
  /** The lux legend's levels (lux mode). */
  levels: number[];
  /** In the daylight-factor view, the outdoor illuminance the levels are a share of (the legend in %). */
  percentOf?: number;
  liveState: NonNullable<ViewerStatus['live']>['state'] | null;
  onBack: () => void;
}

/** What the 3D view shows over its canvas: the light calculation's progress, a lost context, an error, the lux legend, live control's trouble. */
export function ViewerNotes({ progress, error, lost, mode, levels, percentOf, liveState, onBack }: ViewerNotesProps) {
  const { t, format } = useI18n();
  return (
    <>
      {!progress.done && !error && (
        <div className="viewer3d-progress" role="progressbar" aria-label={t('view3d.lightCalculation')} aria-valuemin={0} aria-valuemax={100} aria-valuenow={Math.round(progress.fraction * 100)} data-testid="view3d-progress">
          <div className="viewer3d-progress-bar" style={{ width: `${Math.round(progress.fraction * 100)}%` }} />
          <span>{t(progress.lit ? 'view3d.refining' : 'view3d.computing', { percent: format.percent(progress.fraction) })}</span>
        </div>
      )}
      {lost && (
        <div className="viewer3d-note" role="status">
          {t('view3d.contextLost')}
        </div>
      )}
      {error && (
        <div className="viewer3d-error" role="alert" data-testid="view3d-error">
          <p>{viewerErrorText(t, error)}</p>
          <button type="button" className="btn btn-primary" onClick={onBack}>
            {t('viewer.backTo2d')}
          </button>
        </div>
      )}
      {mode === 'lux' && levels.length > 1 && <LuxLegend levels={levels} percentOf={percentOf} />}
      {(liveState === 'lost' || liveState === 'no-bridge') && (
        <div className="viewer3d-note viewer3d-live-note" role="status" data-testid="live-note">
          {liveState === 'lost' ? t('view3d.liveLost') : t('view3d.liveNoBridge')}
        </div>
      )}
    </>
  );
}
