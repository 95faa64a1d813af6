import { Component, lazy, Suspense, useMemo, type ReactNode } from 'react';
import type { Photometry } from '../../core/photometry/types';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import { setViewerStatus, CLOSED_STATUS } from './viewerStatus';
import { webglSupportIssue } from './webglSupport';
import { useI18n } from '../i18n/useI18n';
import { translateCoded } from '../i18n/translateCoded';

// The 3D chunk (three.js, the baker, the relight engine) is downloaded only when 3D is first opened.
const View3D = lazy(() => import('./View3D'));

export interface LazyView3DProps {
  store: ConfiguratorStore;
  /** The host's photometry loader (catalog paths relative to its asset folder, `assetBase` when embedded). */
  loadPhotometry: (path: string) => Promise<Photometry>;
  onBack: () => void;
  /**
   * False while the planner keeps the view hidden behind the 2D plan (docs/viewer.md, "Always
   * ready"): nothing of it shows, no frames are drawn, and the next 2D → 3D toggle costs one frame.
   */
  visible?: boolean;
  /** Show the expert tools (DMX live control, the photometric files' data notes; docs/embedding.md, option `expert`). */
  expert?: boolean;
  /** Which light the view shows: luminaires, daylight or both (the Daylight panel's buttons; default both). */
  lightSources?: 'electric' | 'daylight' | 'both';
}

function Message({ text, onBack, testId }: { text: string; onBack: () => void; testId: string }) {
  const { t } = useI18n();
  return (
    <section className="view3d-message" role="alert" data-testid={testId}>
      <div>
        <p>{text}</p>
        <button type="button" className="btn btn-primary" onClick={onBack}>
          {t('viewer.backTo2d')}
        </button>
      </div>
    </section>
  );
}

function LoadFailed({ error, onBack }: { error: string; onBack: () => void }) {
  const { t } = useI18n();
  return <Message text={t('viewer.loadFailed', { problem: error })} onBack={onBack} testId="view3d-error" />;
}

/** A failed chunk download or a crash inside the 3D view must not take the planner down. */
class ViewerBoundary extends Component<{ onBack: () => void; visible: boolean; children: ReactNode }, { error: string | null }> {
  override state = { error: null as string | null };
  static getDerivedStateFromError(error: Error) {
    return { error: error.message || 'unknown error' };
  }
  override render() {
    if (this.state.error) return !this.props.visible ? null : <LoadFailed error={this.state.error} onBack={this.props.onBack} />;
    return this.props.children;
  }
}

/** What the 2D/3D toggle shows in 3D: a support check, then the lazily loaded viewer. */
export function LazyView3D({ store, loadPhotometry, onBack, visible = true, expert = false, lightSources = 'both' }: LazyView3DProps) {
  const { t } = useI18n();
  const issue = useMemo(() => webglSupportIssue(), []);
  if (issue) {
    setViewerStatus(store, { ...CLOSED_STATUS, error: issue.text });
    return visible ? <Message text={translateCoded(t, 'viewer', issue)} onBack={onBack} testId="view3d-unsupported" /> : null;
  }
  return (
    <ViewerBoundary onBack={onBack} visible={visible}>
      <Suspense fallback={visible ? <Message text={t('viewer.loading')} onBack={onBack} testId="view3d-loading" /> : null}>
        <View3D store={store} loadPhotometry={loadPhotometry} onBack={onBack} visible={visible} expert={expert} lightSources={lightSources} />
      </Suspense>
    </ViewerBoundary>
  );
}
