import { useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState } from 'react';
import { useStore } from 'zustand';
import type { Photometry } from '../../core/photometry/types';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { QUALITY_LEVEL_NAMES, type QualityLevel } from '../../engines/relight/qualityLevels';
import { objectLightOf } from '../../engines/view/objectLight';
import { objectStats } from '../../engines/view/objectStats';
import { sourceName } from '../../core/model/objects/objectGeometry';
import { PhotometryWarnings, type PhotometryNote } from '../shared/PhotometryWarnings';
import type { ConfiguratorStore, Selection } from '../../core/store/createConfiguratorStore';
import type { Configuration } from '../../core/model/configuration/configuration';
import { CAMERA_PRESETS, type CameraPresetName } from '../../engines/view/cameraPresets';
import { createViewerController, type ViewerController } from '../../engines/view/createViewerController';
import { floorStats, workPlaneStats, type IlluminanceStats } from '../../engines/view/lightStats';
import { DimmerRow } from './DimmerRow';
import { AdaptationControl } from './AdaptationControl';
import { ExposureControl } from './ExposureControl';
import { CompareControl, CompareWipe, useCompare } from './CompareControl';
import { IlluminanceTable } from './IlluminanceTable';
import { LiveControl } from './LiveControl';
import { LuxLegend } from './LuxLegend';
import type { ViewMode } from '../../engines/view/roomView';
import { CLOSED_STATUS, setViewerStatus, type ViewerStatus } from './viewerStatus';
import { bakeHostFor } from './bakeHost';
import type { BakeFeed, ResolvedScene } from './startBakeFeed';
import { aimEvents, SpotlightControls } from './SpotlightControls';
import { INITIAL_CAMERA_MODE, nextCameraMode, presetPressed, type CameraMode, type CameraModeEvent } from './cameraMode';
import './viewer.css';
import { CommitField } from '../shared/CommitField';
import { useI18n } from '../i18n/useI18n';
import type { MessageKey } from '../i18n/messageTypes';
import { viewerErrorText } from './viewerErrorText';
import type { Translate } from '../i18n/messageTypes';
import type { Language } from '../i18n/languages';
import { localName } from '../i18n/localName';
import { furnitureName } from '../i18n/catalogNames';
import { findFurnitureItem } from '../../core/model/objects/furniture/furnitureLibrary';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
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
}

const PRESET_LABEL: Record<CameraPresetName, MessageKey> = { eye: 'view3d.cameraEye', top: 'view3d.cameraTop', corner: 'view3d.cameraCorner' };
const QUALITY_LABEL: Record<QualityLevel, MessageKey> = { fast: 'view3d.qualityFast', balanced: 'view3d.qualityBalanced', best: 'view3d.qualityBest' };

/**
 * The 3D view (lazily loaded chunk: three.js and the room view). The light comes from the
 * configurator's bake service (bakeHost: it outlives the view and is fed every configuration
 * change), so opening the view again after no change shows the baked light at once. Reads the
 * configuration, never changes it except through store actions.
 */
/**
 * The selected object's or module's name for the panel ('Selected: …') as a shopper knows it: a
 * library piece by its name in the UI language, an imported model by its file name, a module by
 * its catalog type's name (never an id); null when nothing of those is selected.
 */
function selectionLabel(t: Translate, language: Language, catalog: Catalog, config: Configuration, selection: Selection): string | null {
  if (!selection) return null;
  if (selection.kind === 'object') {
    const o = config.objects.find((x) => x.id === selection.id);
    if (!o) return null;
    const item = o.source.kind === 'library' ? findFurnitureItem(o.source.item) : undefined;
    return item ? furnitureName(t, item) : sourceName(config, o.source);
  }
  if (selection.kind === 'module') {
    for (const s of config.systems) {
      for (const r of s.rails) {
        for (const m of r.modules) {
          if (m.id !== selection.id) continue;
          const type = catalog.moduleTypes.find((x) => x.id === m.type);
          return t('view3d.selectedModule', { type: type ? localName(type, language) : m.type });
        }
      }
    }
  }
  return null;
}

export default function View3D({ store, loadPhotometry, onBack, visible = true, expert = false }: View3DProps) {
  const { t, format, language } = useI18n();
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const host = useMemo(() => bakeHostFor(store, loadPhotometry), [store, loadPhotometry]);
  const [feed, setFeed] = useState<BakeFeed | null>(() => host.current());
  const [quality, setQuality] = useState<QualityLevel>(host.quality);
  const selection = useStore(store, (s) => s.selection);
  const canvasRef = useRef<HTMLCanvasElement>(null);
  const wrapRef = useRef<HTMLDivElement>(null);
  const ctrl = useRef<ViewerController | null>(null);
  const sceneRef = useRef<BakeScene | null>(null);
  const status = useRef<ViewerStatus>({ ...CLOSED_STATUS, open: true });
  const mountedAt = useRef(0);
  /** The controller's frame count when the view was last shown (firstLitFrame counts from there). */
  const framesAtShow = useRef(0);
  const visibleRef = useRef(visible);
  const unmounted = useRef(false);
  const [progress, setProgress] = useState({ fraction: 0, done: false, lit: false });
  const [error, setError] = useState<string | null>(null);
  const [mode, setMode] = useState<ViewMode>('light');
  // Veiling glare (docs/viewer.md, "Glare"): on by default. Not kept across visits: remembering needs the
  // host's `remember` on the first screen, which is at its download budget.
  const [glare, setGlare] = useState(true);
  const glareRef = useRef(glare);
  // The camera's mode (a preset's orbit or a module's spotlight view): one state for both sets of buttons.
  const [camera, setCamera] = useState<CameraMode>(INITIAL_CAMERA_MODE);
  const cameraEvent = useCallback((e: CameraModeEvent) => setCamera((m) => nextCameraMode(m, e)), []);
  const [levels, setLevels] = useState<number[]>([]);
  const [floor, setFloor] = useState<IlluminanceStats | null>(null);
  const [plane, setPlane] = useState<{ on: boolean; height: number }>({ on: false, height: 0.75 });
  const [planeStats, setPlaneStats] = useState<IlluminanceStats | null>(null);
  const [lost, setLost] = useState(false);
  const [photometryNotes, setPhotometryNotes] = useState<PhotometryNote[]>([]);
  const litRef = useRef<Parameters<Parameters<typeof createViewerController>[2]['onMaps']>[0] | null>(null);
  const [mapsVersion, setMapsVersion] = useState(0);
  /** Counts controllers made, so the aiming controls hand their modes to a new one (its effects run after theirs). */
  const [controllerVersion, setControllerVersion] = useState(0);
  const [liveState, setLiveState] = useState<NonNullable<ViewerStatus['live']>['state'] | null>(null);
  const [compare, updateCompare, compareScenes] = useCompare(feed, ctrl, controllerVersion);

  // The view's own record is kept while it is hidden behind the plan; hosts see a closed view then.
  const publish = (patch: Partial<ViewerStatus>) => {
    if (unmounted.current) return; // late events after unmount
    status.current = { ...status.current, ...patch };
    if (visibleRef.current) setViewerStatus(store, status.current);
  };

  useEffect(() => {
    unmounted.current = false;
    return () => {
      unmounted.current = true;
      status.current = { ...CLOSED_STATUS };
      setViewerStatus(store, status.current);
    };
  }, [store]);

  // Shown (first mount or back from the plan): a new opening, lit on its first frame when the maps are there; hidden: closed, no frames.
  // A layout effect, so the status changes with the screen: React flushes passive effects of a click
  // before the next event, preact (the browser build) only after the next frame.
  useLayoutEffect(() => {
    visibleRef.current = visible;
    if (visible) {
      mountedAt.current = performance.now();
      framesAtShow.current = status.current.frames;
      status.current = { ...status.current, open: true, lit: false, firstLitMs: null, firstLitFrame: null };
      setViewerStatus(store, status.current);
      const wrap = wrapRef.current;
      const r = wrap?.getBoundingClientRect();
      if (r && r.width > 0 && r.height > 0) ctrl.current?.resize(Math.round(r.width), Math.round(r.height));
      ctrl.current?.setActive(true);
    } else {
      ctrl.current?.setActive(false);
      setViewerStatus(store, { ...CLOSED_STATUS });
    }
  }, [visible, store]);

  // The bake service: running already (started in idle time after the planner showed), or started now.
  useEffect(() => {
    if (feed) return;
    let cancelled = false;
    host
      .get()
      .then((f) => !cancelled && setFeed(f))
      .catch((e: Error) => {
        if (cancelled) return;
        const message = `The 3D view could not start: ${e.message}`;
        setError(message);
        publish({ error: message });
      });
    return () => {
      cancelled = true;
    };
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [host, feed]);

  useEffect(() => {
    if (!feed) return;
    const canvas = canvasRef.current!;
    let controller: ViewerController;
    try {
      controller = createViewerController(canvas, feed.service, {
        onProgress: (p) => {
          setProgress({ fraction: p.fraction, done: p.done, lit: p.lit });
          publish({ progress: p.fraction, done: p.done, groupBakes: p.groupBakes, relightsOnly: p.relightsOnly });
        },
        onMaps: (lit, info) => {
          litRef.current = lit;
          setLevels(info.levels);
          const prepared = ctrl.current?.objects() ?? null;
          // The floor a person sees: the texels under furniture standing on it are left out (docs/viewer.md).
          const f = floorStats(lit, prepared);
          setFloor(f);
          setMapsVersion((v) => v + 1);
          const light = objectLightOf(lit);
          const objects = prepared && light && light.atlas.width === prepared.atlas.width && light.atlas.height === prepared.atlas.height ? objectStats(lit, prepared, light) : null;
          publish({ lastRelightMs: info.relightMs, floor: { avg: f.avg, min: f.min, max: f.max, u0: f.u0 }, objects });
        },
        onFrame: (frames) => {
          const patch: Partial<ViewerStatus> = { frames, compare: ctrl.current?.compareState() ?? null };
          if (!status.current.lit && litRef.current) {
            patch.lit = true;
            patch.firstLitMs = performance.now() - mountedAt.current;
            patch.firstLitFrame = frames - framesAtShow.current;
          }
          publish(patch);
        },
        onContext: (state) => {
          setLost(state === 'lost');
          if (state === 'lost') publish({ contextLosses: status.current.contextLosses + 1 });
        },
        onError: (message) => {
          setError(message);
          publish({ error: message });
        },
        // A tap on an object or a module selects it, as a tap in the plan does; a tap on the room clears the selection.
        onPick: (target) => store.getState().select(target),
        // Aiming (docs/aiming.md): a drag in the spotlight view, a tap in aim-at mode.
        ...aimEvents(store),
      });
    } catch (e) {
      const message = `The 3D view could not start: ${(e as Error).message}`;
      publish({ error: message });
      queueMicrotask(() => setError(message));
      return;
    }
    // A fixed EV100 from the page (embed option `exposure`) holds from the first frame.
    if (typeof host.exposure === 'number') controller.setEv100(host.exposure);
    // The chromatic adaptation the page asked for (embed option `adapt`, default eye).
    controller.setAdaptation(host.adaptation);
    controller.setGlare(glareRef.current);
    ctrl.current = controller;
    queueMicrotask(() => setControllerVersion((v) => v + 1));
    // Made while hidden (the feed arrived after the user went back to the plan): no frames until shown.
    controller.setActive(visibleRef.current);
    const wrap = wrapRef.current!;
    const ro = new ResizeObserver(() => {
      const r = wrap.getBoundingClientRect();
      // Hidden behind the plan the box is 0 × 0: keep the last size (the next show resizes anyway).
      if (r.width > 0 && r.height > 0) controller.resize(Math.round(r.width), Math.round(r.height));
    });
    ro.observe(wrap);
    // Every configuration the feed resolved (and handed to the service): the room, fixtures and objects on screen.
    const show = (r: ResolvedScene | null) => {
      if (!r) return;
      sceneRef.current = r.bake;
      controller.setScene(r.bake, r.fixtures, r.ids);
      setPhotometryNotes(r.notes);
    };
    show(feed.latest());
    // The level the service runs at (the device's calibration picks it when nobody chose one).
    const level = feed.service.quality;
    queueMicrotask(() => setQuality(level));
    const failed = feed.error();
    if (failed) queueMicrotask(() => setError(failed));
    const unsubscribe = feed.subscribe(() => {
      setError(feed.error());
      if (!feed.error()) show(feed.latest());
    });
    return () => {
      unsubscribe();
      ro.disconnect();
      // The display only: the service keeps the engine, the maps and any pending bake.
      controller.dispose();
      ctrl.current = null;
    };
    // eslint-disable-next-line react-hooks/exhaustive-deps
  }, [feed]);

  const chooseQuality = (level: QualityLevel) => {
    setQuality(level);
    host.setQuality(level);
  };

  // The selected object or module is highlighted in 3D too (the plan and the view share the store's selection).
  useEffect(() => {
    ctrl.current?.setSelection(selection);
  }, [selection, feed]);
  const selectedLabel = selectionLabel(t, language, catalog, config, selection);

  // Work plane: recomputed when the maps settle or the height changes (direct part on the CPU).
  useEffect(() => {
    if (!plane.on || !litRef.current || !sceneRef.current) {
      setPlaneStats(null);
      return;
    }
    const t = setTimeout(() => setPlaneStats(workPlaneStats(sceneRef.current!, litRef.current!, plane.height, 0.1, {}, ctrl.current?.objects() ?? null)), progress.done ? 0 : 400);
    return () => clearTimeout(t);
  }, [plane, mapsVersion, progress.done]);

  const modules = useMemo(
    () =>
      config.systems.flatMap((s, si) =>
        s.rails.flatMap((r, ri) =>
          r.modules.map((m, mi) => {
            // The shopper's words (issue 27): the catalog's name and the module's place, never its id.
            const type = catalog.moduleTypes.find((x) => x.id === m.type);
            const where = t(config.systems.length > 1 ? 'a11y.moduleInSystem' : 'a11y.module', { index: mi + 1, count: r.modules.length, rail: ri + 1, system: si + 1 });
            return { id: m.id, name: `${type ? localName(type, language) : m.type}, ${where}`, dimming: m.dimming, on: m.on };
          }),
        ),
      ),
    [config, catalog, t, language],
  );
  const maxPlane = config.room.height - 0.1;

  return (
    <section className="viewer3d" aria-label={t('view3d.view')} data-testid="view3d" hidden={!visible}>
      <div className="viewer3d-canvas-wrap" ref={wrapRef}>
        <canvas ref={canvasRef} className="viewer3d-canvas" data-testid="view3d-canvas" />
        <CompareWipe choice={compare} update={updateCompare} scenes={compareScenes} />
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
        {mode === 'lux' && levels.length > 1 && <LuxLegend levels={levels} />}
        {(liveState === 'lost' || liveState === 'no-bridge') && (
          <div className="viewer3d-note viewer3d-live-note" role="status" data-testid="live-note">
            {liveState === 'lost' ? t('view3d.liveLost') : t('view3d.liveNoBridge')}
          </div>
        )}
      </div>
      <div className="viewer3d-panel">
        <div className="viewer3d-group" role="group" aria-label={t('view3d.camera')}>
          {CAMERA_PRESETS.map((p) => (
            <button
              key={p}
              type="button"
              className={`btn${presetPressed(camera, p) ? ' btn-primary' : ''}`}
              aria-pressed={presetPressed(camera, p)}
              onClick={() => {
                setCamera((m) => nextCameraMode(m, { kind: 'preset', name: p }));
                // A preset leaves the spotlight view first (its orbit pose comes back), then moves the orbit camera.
                ctrl.current?.setSpotlight(null);
                ctrl.current?.setPreset(p);
              }}
              data-testid={`camera-${p}`}
            >
              {t(PRESET_LABEL[p])}
            </button>
          ))}
        </div>
        <div className="viewer3d-group" role="group" aria-label={t('view3d.viewMode')}>
          <button
            type="button"
            className={`btn${mode === 'light' ? ' btn-primary' : ''}`}
            aria-pressed={mode === 'light'}
            onClick={() => {
              setMode('light');
              ctrl.current?.setMode('light');
            }}
          >
            {t('view3d.modeLight')}
          </button>
          <button
            type="button"
            className={`btn${mode === 'lux' ? ' btn-primary' : ''}`}
            aria-pressed={mode === 'lux'}
            onClick={() => {
              setMode('lux');
              ctrl.current?.setMode('lux');
            }}
            data-testid="mode-lux"
          >
            {t('view3d.modeLux')}
          </button>
          <button
            type="button"
            className={`btn${glare ? ' btn-primary' : ''}`}
            aria-pressed={glare}
            title={t('view3d.glareHint')}
            onClick={() => {
              setGlare(!glare);
              glareRef.current = !glare;
              ctrl.current?.setGlare(!glare);
            }}
            data-testid="glare-toggle"
          >
            {t('view3d.glare')}
          </button>
        </div>
        <div className="viewer3d-group" role="group" aria-label={t('view3d.quality')}>
          <span className="viewer3d-group-label">{t('view3d.qualityLabel')}</span>
          {QUALITY_LEVEL_NAMES.map((q) => (
            <button key={q} type="button" className={`btn${quality === q ? ' btn-primary' : ''}`} aria-pressed={quality === q} onClick={() => chooseQuality(q)} data-testid={`quality-${q}`}>
              {t(QUALITY_LABEL[q])}
            </button>
          ))}
        </div>
        <ExposureControl initial={host.exposure} target={() => ctrl.current} />
        <AdaptationControl initial={host.adaptation} target={() => ctrl.current} />
        <CompareControl choice={compare} update={updateCompare} scenes={compareScenes} />
        {selectedLabel && (
          <p className="viewer3d-selected" data-testid="view3d-selected" data-kind={selection?.kind} data-id={selection?.id}>
            {t('view3d.selected', { name: selectedLabel })}
          </p>
        )}
        <SpotlightControls store={store} controllerRef={ctrl} ready={controllerVersion} spotlight={camera.spotlight} onCameraMode={cameraEvent} />
        <IlluminanceTable floor={floor} plane={plane.on ? { height: plane.height, stats: planeStats } : null} />
        <label className="viewer3d-field viewer3d-inline">
          <input type="checkbox" checked={plane.on} onChange={(e) => setPlane({ ...plane, on: e.target.checked })} data-testid="plane-on" /> {t('view3d.workPlaneAt')}
          {/* In the locale's format ("0,75" in German), committed on Enter or blur; a height outside 0.1 m … ceiling − 0.1 m goes to the nearest one allowed. */}
          <CommitField label={t('view3d.workPlaneHeight')} value={plane.height} onCommit={(h) => (setPlane({ ...plane, height: Math.min(maxPlane, Math.max(0.1, h)) }), null)} onRefused={() => undefined} testId="plane-height" /> m
        </label>
        {expert && <PhotometryWarnings notes={photometryNotes} testId="view3d-photometry-warnings" collapsed />}
        {modules.length > 0 && (
          <details className="viewer3d-modules">
            <summary>{t('view3d.dimmingModules', { count: modules.length })}</summary>
            {modules.map((m) => (
              <DimmerRow
                key={m.id}
                id={m.id}
                name={m.name}
                dimming={m.dimming}
                onCommit={(d) => store.getState().dispatch('setModuleDimming', { moduleId: m.id, dimming: d })}
                on={m.on !== false}
                onSwitch={(on) => store.getState().dispatch('setModuleOn', { moduleId: m.id, on })}
              />
            ))}
          </details>
        )}
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
