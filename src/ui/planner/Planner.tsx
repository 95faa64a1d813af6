import { lazy, Suspense, useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState, useSyncExternalStore, type DragEvent } from 'react';
import { BrandMark } from '../shared/BrandMark';
import { sentenceStart } from '../i18n/sentenceStart';
import { useStore } from 'zustand';
import { billOfMaterials } from '../../core/model/power/billOfMaterials';
import { installationNeeds } from '../../core/model/power/installationNeeds';
import type { ConfiguratorStore, Selection } from '../../core/store/createConfiguratorStore';
import type { UiStore } from '../../core/store/uiStore';
import { BomPanel } from './BomPanel';
import { LazyOptionsPanel as OptionsPanel } from './LazyOptionsPanel';
import { aimAtMode } from '../shared/aimAtMode';
import { PlanControls } from './PlanControls';
import { PlanSvg } from './PlanSvg';
import { PresetPanel } from './PresetPanel';
import { FURNITURE_DRAG_TYPE, FurniturePanel } from './FurniturePanel';
import { LazyImportPanel } from './LazyImportPanel';
import type { MeshUnits } from '../../core/model/configuration/configuration';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { FilePanel } from './FilePanel';
import { SurfacesPanel } from './SurfacesPanel';
import { LazyDaylightSection } from './LazyDaylightSection';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { LazyView3D } from '../viewer/LazyView3D';

// The share link's copy and share buttons load once a link is made (not with the first screen).
const ShareLinkField = lazy(() => import('./ShareLinkField'));
// The Expert switch loads only where the shop offers it (docs/embedding.md, option `expert`).
const ExpertSwitch = lazy(() => import('./ExpertSwitch'));
import { lowMemoryDevice } from '../../engines/view/lowMemoryDevice';
import { createActionGate } from './actionGate';
import { detailLevel } from './detailLevel';
import { useI18n } from '../i18n/useI18n';
import { LanguageSwitch } from '../i18n/LanguageSwitch';
import { noticeText } from '../i18n/noticeText';
import { selectionPath } from './selection';
import { usePlanGestures } from './usePlanGestures';
import { usePlanView } from './usePlanView';
import type { Viewport } from './viewTransform';
import { BottomBar } from './BottomBar';
import { CommandButton } from './CommandButton';
import { DEFAULT_VIEWPORT, PlannerController } from './PlannerController';
import { addImportedModel, addLibraryItem } from './addFurniture';
import type { FootprintSource } from './footprintSource';
import { requestFootprints } from './moduleFootprint';
import { usePlannerKeys } from './usePlannerKeys';
import { useFitCompact } from './useFitCompact';
import { LazyScenePanel as ScenePanel } from '../scenes/LazyScenePanel';
import { scenePlayerHandle } from '../scenes/scenePlayerHandle';
import { mixLevels, outputLevels } from '../../core/model/cues/sceneFade';
import { PlanAnnouncer } from './PlanAnnouncer';
import type { Landmarks } from '../shared/landmarks';
import type { FirstRunOptions } from './FirstRunHint';
import { LazyGuidance } from './lazyGuidance';
import { LazyRoomShapeEditor } from './LazyRoomShape';

export interface PlannerProps {
  store: ConfiguratorStore;
  ui: UiStore;
  /** Show the language switch in the top bar. */
  languageSwitch?: boolean;
  /** Shows the room-setup screen again. */
  onNewRoom: () => void;
  /** Copies a share link; returns the message to show. */
  onShare: () => string;
  /** What the last share link left out (imported models), shown next to it; null when it is complete. */
  shareNotice?: string | null;
  footprints: FootprintSource;
  /** 'page': the header is the page's banner and the plan its main (the standalone app); 'region': inside the embed's region. */
  landmarks?: Landmarks;
  /** The empty plan's suggestions (docs/planner.md, "First run"): false hides them; `presets` picks the shop's own (docs/embedding.md). */
  firstRun?: FirstRunOptions | false;
}

/** The box width (px) up to which the side panel is a drawer: `@container luxbox (max-width: 900px)` in app.css. */
const DRAWER_MAX_WIDTH = 900;

/** The main screen (configurator paper, fig. 6): the plan, side panel with presets and price, bottom bar. */
export function Planner({ store, ui, languageSwitch = false, onNewRoom, onShare, shareNotice = null, footprints, landmarks = 'region', firstRun }: PlannerProps) {
  const { t, format, language, locale } = useI18n();
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const selection = useStore(store, (s) => s.selection);
  const mode = useStore(ui, (s) => s.mode);
  const optionsOpen = useStore(ui, (s) => s.optionsOpen);
  const panelOpen = useStore(ui, (s) => s.panelOpen);
  const status = useStore(ui, (s) => s.status);
  const shareLink = useStore(ui, (s) => s.shareLink);
  const expert = useStore(ui, (s) => s.expert);
  const expertSwitch = useStore(ui, (s) => s.expertSwitch);
  const roomEdit = useStore(ui, (s) => s.roomEdit);

  const wrapRef = useRef<HTMLDivElement>(null);
  const [viewport, setViewport] = useState<Viewport>(DEFAULT_VIEWPORT);
  // Everything the plan does with input lives in the controller; React draws what it holds.
  const controller = useMemo(() => new PlannerController(store, ui), [store, ui]);
  // Before the command buttons below render: their labels and reasons come in this language.
  controller.setTranslator(t);
  const view = usePlanView(controller);
  const drag = useSyncExternalStore(controller.subscribe, () => controller.drag);
  const { explain, run } = controller;
  const gate = useMemo(() => createActionGate(config, catalog, run, explain, (r) => noticeText(t, language, catalog, r)), [config, catalog, run, explain, t, language]);
  const path = selectionPath(config, selection);
  const select = useCallback((sel: Selection) => store.getState().select(sel), [store]);
  const bom = useMemo(() => billOfMaterials(config, catalog), [config, catalog]);
  // The room-shape mode's bar and sheet cover the plan's edges: the room is fitted between them.
  const fitBetween = useCallback((top: number, bottom: number) => controller.setFitInsets(top, bottom), [controller]);
  const needs = useMemo(() => installationNeeds(config, catalog), [config, catalog]);

  // Fit the room when the plan first gets its size and whenever the room's dimensions change.
  const roomKey = `${config.room.width}x${config.room.depth}`;
  useLayoutEffect(() => {
    const el = wrapRef.current;
    if (!el) return;
    const measure = () => {
      const r = el.getBoundingClientRect();
      if (r.width < 1 || r.height < 1) return;
      const vp = { width: Math.round(r.width), height: Math.round(r.height) };
      setViewport((old) => (old.width === vp.width && old.height === vp.height ? old : vp));
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => ro.disconnect();
  }, [mode]);
  // roomKey is a dependency on purpose: setViewport refits when the room's size changed.
  useLayoutEffect(() => controller.setViewport(viewport), [roomKey, viewport, controller]);

  useEffect(() => {
    requestFootprints(
      footprints,
      config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)),
      catalog,
    );
  }, [footprints, config, catalog]);

  // Status messages disappear after a few seconds (they explain, they do not block).
  useEffect(() => {
    if (!status) return;
    const t = window.setTimeout(() => ui.setState({ status: null }), 4000);
    return () => window.clearTimeout(t);
  }, [status, ui]);

  // The options sit at the top of the side panel: show them when they open, wherever the panel was scrolled to (the furniture list, say).
  const panelRef = useRef<HTMLElement>(null);
  useEffect(() => {
    if (optionsOpen && panelRef.current) panelRef.current.scrollTop = 0;
  }, [optionsOpen, selection]);

  // A light-scene crossfade: the plan shows each module's level as it fades (docs/light-scenes.md).
  const player = scenePlayerHandle(store);
  const fading = useSyncExternalStore(player.subscribe, () => player.getState().fading);
  const fadeLevelsShown = useMemo(() => (fading ? mixLevels(fading.fromLevels, outputLevels(fading.to), fading.e) : null), [fading]);

  // The header's texts at full length where they fit, the drawer toggle as an icon where they do not.
  const headerRef = useRef<HTMLElement>(null);
  useFitCompact(headerRef);

  // Whether the side panel is a drawer: the same 900 px of the box as the container query in app.css.
  const bodyRef = useRef<HTMLDivElement>(null);
  useLayoutEffect(() => {
    const el = bodyRef.current;
    if (!el) return;
    const measure = () => {
      const drawer = el.getBoundingClientRect().width <= DRAWER_MAX_WIDTH;
      if (ui.getState().drawer !== drawer) ui.setState({ drawer });
    };
    measure();
    const ro = new ResizeObserver(measure);
    ro.observe(el);
    return () => ro.disconnect();
  }, [ui]);
  const closeDrawer = () => ui.setState({ panelOpen: false });
  // A press beside the open drawer closes it and still reaches what it was on (the plan, a bottom-bar
  // button): the veil only dims what is beside the drawer and takes no taps. The header's
  // toggle closes it by itself, and a tip at a refused control in the drawer belongs to the drawer.
  useEffect(() => {
    const body = bodyRef.current;
    if (!panelOpen || !body) return;
    const press = (e: PointerEvent) => {
      const target = e.target as Element;
      if (ui.getState().drawer && !panelRef.current?.contains(target) && !target.closest('.panel-toggle, .disabled-tip')) ui.setState({ panelOpen: false });
    };
    body.addEventListener('pointerdown', press, true);
    return () => body.removeEventListener('pointerdown', press, true);
  }, [panelOpen, ui]);

  usePlanGestures(wrapRef, controller);
  usePlannerKeys(controller, mode === '2d');
  // Once opened, the 3D view stays mounted (hidden) behind the plan, so going back to 3D draws one
  // frame instead of building a renderer and uploading the maps again; not on low-memory devices.
  const [keep3d, setKeep3d] = useState(false);
  // Adjusting state while rendering (React's pattern for state that follows another value): no extra effect pass.
  if (mode === '3d' && !keep3d && !lowMemoryDevice()) setKeep3d(true);
  const level = detailLevel(view.scale);

  // A library item tapped in the panel goes to the middle of the visible plan; the drawer closes to show it.
  const addFurniture = (itemId: string) => {
    if (addLibraryItem(controller, itemId) === null) ui.setState({ panelOpen: false });
  };
  const addImported = (name: string, mesh: TriangleMesh, units: MeshUnits) => {
    const refused = addImportedModel(controller, name, mesh, units);
    if (refused === null) ui.setState({ panelOpen: false });
    // The refusal just went to the status line with its code: the import panel shows it in the same words.
    const status = ui.getState().status;
    return refused === null ? null : status?.text === refused ? noticeText(t, language, catalog, status) : refused;
  };
  // A library item dragged from the panel and dropped on the plan lands where it was dropped.
  const dragOver = (e: DragEvent) => {
    if (!e.dataTransfer.types.includes(FURNITURE_DRAG_TYPE)) return;
    e.preventDefault();
    e.dataTransfer.dropEffect = 'copy';
  };
  const drop = (e: DragEvent) => {
    const itemId = e.dataTransfer.getData(FURNITURE_DRAG_TYPE);
    const el = wrapRef.current;
    if (!itemId || !el) return;
    e.preventDefault();
    const r = el.getBoundingClientRect();
    addLibraryItem(controller, itemId, { sx: e.clientX - r.left, sy: e.clientY - r.top });
  };

  const placedNew = () => {
    const systems = store.getState().config.systems;
    const last = systems[systems.length - 1];
    if (last) select({ kind: 'system', id: last.id });
    ui.setState({ panelOpen: false });
  };

  // The plan, the 3D view and the bottom bar are the main landmark of a page; the side panel an aside beside it.
  const WorkArea = landmarks === 'page' ? 'main' : 'div';
  return (
    <div className="app-body" ref={bodyRef}>
      <PlanAnnouncer store={store} />
      <header ref={headerRef} className="app-header">
        <BrandMark ui={ui} />
        <span className="room-label">{t('planner.roomSize', { width: config.room.width, depth: config.room.depth, height: config.room.height })}</span>
        <span className="spacer" />
        {languageSwitch && <LanguageSwitch />}
        <span className="total" data-testid="header-total" aria-label={t('planner.totalPrice')}>
          {format.money(bom.total, bom.currency)}
        </span>
        <button
          type="button"
          className="btn panel-toggle"
          aria-expanded={panelOpen}
          aria-label={panelOpen ? t('common.close') : t('planner.presetsToggle')}
          title={panelOpen ? t('common.close') : t('planner.presetsToggle')}
          data-testid="panel-toggle"
          onClick={() => (panelOpen ? closeDrawer() : ui.setState({ panelOpen: true }))}
        >
          <span className="toggle-text">{panelOpen ? t('common.close') : t('planner.presetsToggle')}</span>
        </button>
      </header>
      <div className="workspace">
        {/* A disabled control's reason in a tip at the control (docs/planner.md, "Reasons at the control"). */}
        <LazyGuidance tips={{ store, mode, explain }} />
        <WorkArea className="stage">
          {mode === '2d' ? (
            <div className="plan-wrap" ref={wrapRef} data-testid="plan" data-scale={view.scale.toFixed(3)} data-level={level} onDragOver={dragOver} onDrop={drop}>
              <PlanSvg config={config} catalog={catalog} view={view} selection={path} drag={drag} footprints={footprints} levels={fadeLevelsShown} />
              <PlanControls
                config={config}
                catalog={catalog}
                view={view}
                viewport={viewport}
                level={level}
                selection={path}
                gate={gate}
                onSelect={select}
                onOpenOptions={() => ui.setState({ optionsOpen: true, panelOpen: true })}
                drag={drag}
              />
              <div className="zoom-controls" data-plan-control>
                <CommandButton controller={controller} id="zoom-in" testId="zoom-in">
                  +
                </CommandButton>
                <CommandButton controller={controller} id="zoom-out" testId="zoom-out">
                  −
                </CommandButton>
                <CommandButton controller={controller} id="zoom-fit" testId="zoom-fit">
                  ⤢
                </CommandButton>
              </div>
              {config.systems.length === 0 && config.objects.length === 0 && firstRun !== false && !roomEdit && (
                <LazyGuidance
                  firstRun={{
                    room: config.room,
                    catalog,
                    gate,
                    options: firstRun,
                    onPlaced: placedNew,
                    ui,
                  }}
                />
              )}
              {roomEdit && (
                <LazyRoomShapeEditor
                  config={config}
                  view={view}
                  gate={gate}
                  onInsets={fitBetween}
                  onDone={() => {
                    controller.setFitInsets(0, 0);
                    ui.setState({ roomEdit: false });
                  }}
                />
              )}
              {status && (
                <div className="status-line" role="status" data-testid="status-line" key={status.seq}>
                  {sentenceStart(noticeText(t, language, catalog, status), locale)}
                </div>
              )}
            </div>
          ) : null}
          {/* One place in the tree, so the view survives the 2D plan: kept hidden once opened (keep3d), shown again at the next toggle. */}
          {(mode === '3d' || keep3d) && <LazyView3D store={store} loadPhotometry={footprints.loadPhotometry} onBack={() => ui.setState({ mode: '2d' })} visible={mode === '3d'} expert={expert} />}
          <BottomBar controller={controller} mode={mode} />
        </WorkArea>
        {/* The veil beside the open drawer: a press there closes the drawer and goes on to what is under it (the effect above). Keyboard users have the header's toggle. */}
        {panelOpen && <div className="drawer-scrim" aria-hidden data-testid="drawer-scrim" />}
        <aside ref={panelRef} className={`side-panel${panelOpen ? ' open' : ''}`} aria-label={t('planner.sidePanel')}>
          {/* A module's photometric data notes are an expert tool: without the loader the options show none. */}
          {optionsOpen && <OptionsPanel config={config} catalog={catalog} path={path} gate={gate} onClose={() => ui.setState({ optionsOpen: false })} footprints={expert ? footprints : undefined} aimMode={aimAtMode(store)} />}
          <PresetPanel
            catalog={catalog}
            gate={gate}
            onPlaced={placedNew}
            onLoadRoom={(room) => {
              const result = store.getState().load(room);
              if (!result.ok) return explain(result.reason);
              // Show the room that replaced the old one: the drawer closes, nothing stays selected.
              store.getState().select(null);
              ui.setState({ panelOpen: false, optionsOpen: false });
            }}
          />
          <FurniturePanel gate={gate} onAdd={addFurniture}>
            <LazyImportPanel onAdd={addImported} />
          </FurniturePanel>
          <ScenePanel store={store} />
          <SurfacesPanel room={config.room} finishes={defaultSurfaceFinishes} gate={gate} onEditShape={() => ui.setState({ roomEdit: true, mode: '2d', panelOpen: false, optionsOpen: false })} />
          <LazyDaylightSection config={config} gate={gate} />
          <BomPanel bom={bom} needs={needs} catalog={catalog} />
          <section className="panel-section">
            <div className="setup-actions">
              <button type="button" className="btn" onClick={() => explain(onShare())} data-testid="share">
                {t('planner.shareLink')}
              </button>
              <button type="button" className="btn" onClick={onNewRoom}>
                {t('planner.newRoom')}
              </button>
            </div>
            <FilePanel store={store} ui={ui} loadPhotometry={footprints.loadPhotometry} />
            {expertSwitch && (
              <Suspense fallback={null}>
                <ExpertSwitch ui={ui} />
              </Suspense>
            )}
            {shareLink && (
              <Suspense fallback={null}>
                <ShareLinkField link={shareLink} notice={shareNotice} />
              </Suspense>
            )}
          </section>
        </aside>
      </div>
    </div>
  );
}
