import { useMemo, useRef, useState } from 'react';
import { useStore } from 'zustand';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { QualityLevel } from '../../engines/relight/qualityLevels';
import type { LitMaps } from '../../engines/relight/relightMaps';
import { PhotometryWarnings, type PhotometryNote } from '../shared/PhotometryWarnings';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { ViewerController } from '../../engines/view/createViewerController';
import type { IlluminanceStats } from '../../engines/view/lightStats';
import { AdaptationControl } from './AdaptationControl';
import { ExposureControl } from './ExposureControl';
import { CompareControl, CompareWipe, useCompare } from './CompareControl';
import { IlluminanceTable } from './IlluminanceTable';
import { LiveControl } from './LiveControl';
import type { ViewerStatus } from './viewerStatus';
import { bakeHostFor } from './bakeHost';
import type { BakeFeed } from './startBakeFeed';
import { SpotlightControls } from './SpotlightControls';
import './viewer.css';
import { useI18n } from '../i18n/useI18n';
import { SelectionNote } from './SelectionNote';
import { useViewerStatus } from './useViewerStatus';
import { useFeedStart } from './useFeedStart';
import { useViewerController } from './useViewerController';
import { useWorkPlaneStats } from './useWorkPlaneStats';
import { useDaylightFactorView } from './useDaylightFactorView';
import { DaylightFactorTable } from './DaylightFactorTable';
import { DAYLIGHT_FACTOR_SKY_ILLUMINANCE } from '../../core/daylight/daylightFactor';
import { ViewerNotes } from './ViewerNotes';
import { CameraPresetButtons } from './CameraPresetButtons';
import { ViewModeButtons } from './ViewModeButtons';
import { QualityButtons } from './QualityButtons';
import { WorkPlaneField, type WorkPlane } from './WorkPlaneField';
import { ModuleDimmers } from './ModuleDimmers';
import { useSelectionHighlight } from './useSelectionHighlight';
import { useViewerToggles } from './useViewerToggles';
import './registerView3dEnglish';

export interface View3DProps {
  store: ConfiguratorStore;
  /** The host's photometry loader (the plan's footprints load through the same one and cache). */
  loadPhotometry: (path: string) => Promise<Photometry>;
  onBack: () => void;
  /** False while the planner keeps the view hidden behind the 2D plan: no frames, status closed (LazyView3D). */
  visible?: boolean;
  /** Show the expert tools: DMX live control and the photometric files' data notes (docs/embedding.md, option `expert`). */
  expert?: boolean;
  /** Which light the view shows (LazyView3D): the controller re-weights the engine's bases and redraws the window panes, no bake. */
  lightSources?: 'electric' | 'daylight' | 'both';
}

/**
 * The 3D view (lazily loaded chunk: three.js and the room view). The light comes from the
 * configurator's bake service (bakeHost: it outlives the view and is fed every configuration
 * change), so opening the view again after no change shows the baked light at once. Reads the
 * configuration, never changes it except through store actions. The controller and its events
 * live in useViewerController, the status for hosts in useViewerStatus; the panel's parts are
 * components of their own.
 */
export default function View3D({ store, loadPhotometry, onBack, visible = true, expert = false, lightSources = 'both' }: View3DProps) {
  const { t } = useI18n();
  const config = useStore(store, (s) => s.config);
  const host = useMemo(() => bakeHostFor(store, loadPhotometry), [store, loadPhotometry]);
  const [feed, setFeed] = useState<BakeFeed | null>(() => host.current());
  const [quality, setQuality] = useState<QualityLevel>(host.quality);
  const selection = useStore(store, (s) => s.selection);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const wrapRef = useRef<HTMLDivElement>(null);
  const ctrl = useRef<ViewerController | null>(null);
  const sceneRef = useRef<BakeScene | null>(null);
  const [progress, setProgress] = useState({ fraction: 0, done: false, lit: false });
  const [error, setError] = useState<string | null>(null);
  const { mode, chooseMode, glare, glareRef, switchGlare, camera, cameraEvent, choosePreset } = useViewerToggles(ctrl);
  const [levels, setLevels] = useState<number[]>([]);
  const [floor, setFloor] = useState<IlluminanceStats | null>(null);
  const [plane, setPlane] = useState<WorkPlane>({ on: false, height: 0.75 });
  const [planeStats, setPlaneStats] = useState<IlluminanceStats | null>(null);
  const [lost, setLost] = useState(false);
  const [photometryNotes, setPhotometryNotes] = useState<PhotometryNote[]>([]);
  const litRef = useRef<LitMaps | null>(null);
  const [mapsVersion, setMapsVersion] = useState(0);
  /** Counts controllers made, so the aiming controls hand their modes to a new one (its effects run after theirs). */
  const [controllerVersion, setControllerVersion] = useState(0);
  const [liveState, setLiveState] = useState<NonNullable<ViewerStatus['live']>['state'] | null>(null);
  const [compare, updateCompare, compareScenes] = useCompare(feed, ctrl, controllerVersion);

  const record = useViewerStatus(store, visible, ctrl, wrapRef);
  const { publish } = record;
  useFeedStart(host, feed, setFeed, (message) => {
    setError(message);
    publish({ error: message });
  });
  const shown = { setProgress, setLevels, setFloor, setPlaneStats, setMapsVersion, setLost, setError, setControllerVersion, setPhotometryNotes, setQuality };
  useViewerController({ feed, store, host, canvasRef, wrapRef, controllerRef: ctrl, sceneRef, litRef, glareRef, record, shown });

  useSelectionHighlight(ctrl, selection, feed);
  // A new controller starts from the service's choice; the panel's choice wins (weights only, never a bake), unless the daylight-factor mode is on.
  const daylightAvailable = config.daylight?.on === true && (config.room.shape?.openings ?? []).some((o) => o.kind === 'window');
  const df = useDaylightFactorView({ available: daylightAvailable, visible, lightSources, controllerRef: ctrl, controllerVersion, sceneRef, publish });
  useWorkPlaneStats({ plane, mapsVersion, done: progress.done, sceneRef, litRef, controllerRef: ctrl, controllerVersion, setPlaneStats, publish });

  return (
    <section className="viewer3d" aria-label={t('view3d.view')} data-testid="view3d" hidden={!visible}>
      <div className="viewer3d-canvas-wrap" ref={wrapRef}>
        <canvas ref={canvasRef} className="viewer3d-canvas" data-testid="view3d-canvas" />
        <CompareWipe choice={compare} update={updateCompare} scenes={compareScenes} />
        <ViewerNotes progress={progress} error={error} lost={lost} mode={mode} levels={levels} percentOf={df.on ? DAYLIGHT_FACTOR_SKY_ILLUMINANCE : undefined} liveState={liveState} onBack={onBack} />
      </div>
      <div className="viewer3d-panel">
        <CameraPresetButtons camera={camera} onPreset={choosePreset} />
        <ViewModeButtons mode={mode} glare={glare} onMode={chooseMode} onGlare={switchGlare} daylightFactor={daylightAvailable ? { on: df.on, choose: df.choose } : undefined} />
        <QualityButtons quality={quality} onChoose={(level) => (setQuality(level), host.setQuality(level))} />
        <ExposureControl initial={host.exposure} target={() => ctrl.current} />
        <AdaptationControl initial={host.adaptation} target={() => ctrl.current} />
        <CompareControl choice={compare} update={updateCompare} scenes={compareScenes} />
        <SelectionNote store={store} />
        <SpotlightControls store={store} controllerRef={ctrl} ready={controllerVersion} spotlight={camera.spotlight} onCameraMode={cameraEvent} />
        {df.on ? <DaylightFactorTable values={df.values} /> : <IlluminanceTable floor={floor} plane={plane.on ? { height: plane.height, stats: planeStats } : null} />}
        <WorkPlaneField plane={plane} maxHeight={config.room.height - 0.1} onChange={setPlane} />
        {expert && <PhotometryWarnings notes={photometryNotes} testId="view3d-photometry-warnings" collapsed />}
        <ModuleDimmers store={store} />
        {/* Unmounted when the expert tools go off: live control stops with it (its cleanup closes the bridge). */}
        {expert && (
          <LiveControl
            store={store}
            onLevels={(l) => ctrl.current?.setLiveLevels(l)}
            onStatus={(live) => {
              setLiveState(live?.state ?? null);
              publish({ live });
            }}
          />
        )}
        <button type="button" className="btn" onClick={onBack} data-testid="back-2d">
          {t('viewer.backTo2d')}
        </button>
      </div>
    </section>
  );
}
