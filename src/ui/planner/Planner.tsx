import { useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState, useSyncExternalStore } from 'react';
import { useStore } from 'zustand';
import { billOfMaterials } from '../../core/model/power/billOfMaterials';
import { installationNeeds } from '../../core/model/power/installationNeeds';
import type { ConfiguratorStore, Selection } from '../../core/store/createConfiguratorStore';
import type { UiStore } from '../../core/store/uiStore';
import { lowMemoryDevice } from '../../engines/view/lowMemoryDevice';
import { noticeText } from '../i18n/noticeText';
import { useI18n } from '../i18n/useI18n';
import type { Landmarks } from '../shared/landmarks';
import { LazyView3D } from '../viewer/LazyView3D';
import { createActionGate } from './actionGate';
import { BottomBar } from './BottomBar';
import type { FirstRunOptions } from './FirstRunHint';
import type { FootprintSource } from './footprintSource';
import { LazyGuidance } from './lazyGuidance';
import { requestFootprints } from './moduleFootprint';
import { PlanAnnouncer } from './PlanAnnouncer';
import { PlannerController } from './PlannerController';
import { PlannerHeader } from './PlannerHeader';
import type { PlannerScope } from './plannerScope';
import { PlannerSidePanel } from './PlannerSidePanel';
import { PlanPane } from './PlanPane';
import { selectionPath } from './selection';
import { useDrawer, usePlanViewport, useStatusExpiry } from './usePlannerLayout';
import { usePlanGestures } from './usePlanGestures';
import { usePlannerKeys } from './usePlannerKeys';
import { usePlanView } from './usePlanView';

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

/**
 * The main screen (configurator paper, fig. 6): the plan, side panel with presets and price, bottom bar.
 * Its parts (PlannerHeader, PlanPane, PlannerSidePanel) share one PlannerScope (plannerScope.ts).
 */
export function Planner(props: PlannerProps) {
  const { store, ui, footprints } = props;
  const i18n = useI18n();
  const { t, language } = i18n;
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const selection = useStore(store, (s) => s.selection);
  // The UI state the parts show (mode, panels, status line, share link, Expert, room editing).
  const u = useStore(ui);

  const wrapRef = useRef<HTMLDivElement>(null);
  // Everything the plan does with input lives in the controller; React draws what it holds.
  const controller = useMemo(() => new PlannerController(store, ui), [store, ui]);
  // Before the command buttons below render: their labels and reasons come in this language.
  controller.setTranslator(t);
  const view = usePlanView(controller);
  const drag = useSyncExternalStore(controller.subscribe, () => controller.drag);
  const { explain, run } = controller;
  const gate = useMemo(() => createActionGate(config, catalog, run, explain, (r) => noticeText(t, language, catalog, r)), [config, catalog, run, explain, t, language]);
  const select = useCallback((sel: Selection) => store.getState().select(sel), [store]);
  const bom = useMemo(() => billOfMaterials(config, catalog), [config, catalog]);
  const needs = useMemo(() => installationNeeds(config, catalog), [config, catalog]);

  // Fit the room when the plan first gets its size and whenever the room's dimensions change.
  const viewport = usePlanViewport(wrapRef, u.mode);
  const roomKey = `${config.room.width}x${config.room.depth}`;
  // roomKey is a dependency on purpose: setViewport refits when the room's size changed.
  useLayoutEffect(() => controller.setViewport(viewport), [roomKey, viewport, controller]);
  useEffect(() => {
    requestFootprints(
      footprints,
      config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)),
      catalog,
    );
  }, [footprints, config, catalog]);
  useStatusExpiry(ui, u.status);
  const bodyRef = useRef<HTMLDivElement>(null);
  const panelRef = useRef<HTMLElement>(null);
  useDrawer(ui, bodyRef, panelRef, u.panelOpen);
  usePlanGestures(wrapRef, controller);
  usePlannerKeys(controller, u.mode === '2d');
  // Once opened, the 3D view stays mounted (hidden) behind the plan, so going back to 3D draws one
  // frame instead of building a renderer and uploading the maps again; not on low-memory devices.
  const [keep3d, setKeep3d] = useState(false);
  // Adjusting state while rendering (React's pattern for state that follows another value): no extra effect pass.
  if (u.mode === '3d' && !keep3d && !lowMemoryDevice()) setKeep3d(true);

  const placedNew = () => {
    const systems = store.getState().config.systems;
    const last = systems[systems.length - 1];
    if (last) select({ kind: 'system', id: last.id });
    ui.setState({ panelOpen: false });
  };
  const path = selectionPath(config, selection);
  const p: PlannerScope = { ...props, ...i18n, ...u, config, catalog, selection, controller, view, viewport, drag, gate, path, select, bom, needs, wrapRef, panelRef, placedNew };
  // The plan, the 3D view and the bottom bar are the main landmark of a page; the side panel an aside beside it.
  const WorkArea = props.landmarks === 'page' ? 'main' : 'div';
  return (
    <div className="app-body" ref={bodyRef}>
      <PlanAnnouncer store={store} />
      <PlannerHeader p={p} />
      <div className="workspace">
        {/* A disabled control's reason in a tip at the control (docs/planner.md, "Reasons at the control"). */}
        <LazyGuidance tips={{ store, mode: u.mode, explain }} />
        <WorkArea className="stage">
          {u.mode === '2d' ? <PlanPane p={p} /> : null}
          {/* One place in the tree, so the view survives the 2D plan: kept hidden once opened (keep3d), shown again at the next toggle. */}
          {(u.mode === '3d' || keep3d) && <LazyView3D store={store} loadPhotometry={footprints.loadPhotometry} onBack={() => ui.setState({ mode: '2d' })} visible={u.mode === '3d'} expert={u.expert} lightSources={u.lightSources} />}
          <BottomBar controller={controller} mode={u.mode} />
        </WorkArea>
        {/* The veil beside the open drawer: a press there closes the drawer and goes on to what is under it (useDrawer). Keyboard users have the header's toggle. */}
        {u.panelOpen && <div className="drawer-scrim" aria-hidden data-testid="drawer-scrim" />}
        <PlannerSidePanel p={p} />
      </div>
    </div>
  );
}
