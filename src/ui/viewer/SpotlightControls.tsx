import './registerView3dEnglish';
import { useEffect, useMemo } from 'react';
import { useStore } from 'zustand';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { ModuleAim } from '../../core/model/configuration/configuration';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { ViewerController } from '../../engines/view/createViewerController';
import { useI18n } from '../i18n/useI18n';
import { aimAtMode, useAimAt } from '../shared/aimAtMode';
import { spotlightRequest } from './spotlightRequest';
import type { CameraModeEvent } from './cameraMode';

/**
 * The viewer's events for aiming (docs/aiming.md): a released drag in the spotlight view sets the
 * aim (one undoable setAim), a tap in aim-at mode aims the mode's module at the point (aimAt) and
 * ends the mode.
 */
export function aimEvents(store: ConfiguratorStore) {
  return {
    onAim(moduleId: string, aim: ModuleAim) {
      store.getState().dispatch('setAim', { moduleId, aim });
    },
    onAimAt(point: Vec3) {
      const mode = aimAtMode(store);
      const moduleId = mode.get();
      if (!moduleId) return;
      store.getState().dispatch('aimAt', { moduleId, point: [point[0], point[1], point[2]] });
      mode.set(null);
    },
  };
}

export interface SpotlightControlsProps {
  store: ConfiguratorStore;
  controllerRef: { readonly current: ViewerController | null };
  /** Changes when a new controller exists (the feed arrived), so the modes are handed to it again. */
  ready: unknown;
  /** The module whose spotlight view the camera shows (the view's CameraMode), or null. */
  spotlight: string | null;
  /** Enter or leave the spotlight view, or report the selection's adjustable module (cameraMode.ts). */
  onCameraMode: (event: CameraModeEvent) => void;
}

/**
 * The 3D panel's aiming controls for a selected adjustable module: enter/leave the spotlight view
 * (a camera at the module along its axis; dragging pans and tilts it) and aim at a tapped point.
 * Nothing for other selections; the spotlight view ends when the selection leaves the module.
 */
export function SpotlightControls({ store, controllerRef, ready, spotlight, onCameraMode }: SpotlightControlsProps) {
  const { t } = useI18n();
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const selection = useStore(store, (s) => s.selection);
  const aimAt = useAimAt(store);
  const target = useMemo(() => (selection?.kind === 'module' ? spotlightRequest(config, catalog, selection.id) : null), [selection, config, catalog]);
  const spotOn = spotlight !== null && target?.moduleId === spotlight;
  // The selection left the module (or it is no longer adjustable): its spotlight view ends, in the state too.
  const targetId = target?.moduleId ?? null;
  useEffect(() => onCameraMode({ kind: 'selection', moduleId: targetId }), [targetId, onCameraMode]);
  useEffect(() => {
    controllerRef.current?.setSpotlight(spotOn ? target : null);
  }, [spotOn, target, controllerRef, ready]);
  useEffect(() => {
    controllerRef.current?.setAimAt(aimAt !== null);
  }, [aimAt, controllerRef, ready]);
  if (!target) return null;
  const aimingHere = aimAt === target.moduleId;
  return (
    <div className="viewer3d-group" role="group" aria-label={t('aim.title')} data-testid="view3d-aim">
      <button
        type="button"
        className={`btn${spotOn ? ' btn-primary' : ''}`}
        aria-pressed={spotOn}
        title={t('aim.spotlightHint')}
        onClick={() => onCameraMode({ kind: 'spotlight', moduleId: spotOn ? null : target.moduleId })}
        data-testid="spotlight-view"
      >
        {spotOn ? t('aim.spotlightLeave') : t('aim.spotlightView')}
      </button>
      <button type="button" className={`btn${aimingHere ? ' btn-primary' : ''}`} aria-pressed={aimingHere} title={t('aim.aimAtHint')} onClick={() => aimAtMode(store).set(aimingHere ? null : target.moduleId)} data-testid="view3d-aim-at">
        {aimingHere ? t('aim.cancel') : t('aim.aimAt')}
      </button>
      {spotOn && (
        <p className="viewer3d-hint" role="status" data-testid="spotlight-hint">
          {t('aim.spotlightHint')}
        </p>
      )}
      {aimingHere && (
        <p className="viewer3d-hint" role="status">
          {t('aim.aimAtActive')}
        </p>
      )}
    </div>
  );
}
