import { useCallback, useEffect, useLayoutEffect, useMemo, useRef, useState } from 'react';
import { useStore } from 'zustand';
import { billOfMaterials } from '../../core/model/billOfMaterials';
import type { ConfiguratorStore, Selection } from '../../core/store/createConfiguratorStore';
import { type UiStore, showStatus } from '../../core/store/uiStore';
import { ActionButton } from './ActionButton';
import { BomPanel } from './BomPanel';
import { OptionsPanel } from './OptionsPanel';
import { PlanControls } from './PlanControls';
import { PlanSvg } from './PlanSvg';
import { PresetPanel } from './PresetPanel';
import { FilePanel } from './FilePanel';
import { SurfacesPanel } from './SurfacesPanel';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { LazyView3D } from '../viewer/LazyView3D';
import { createActionGate } from './actionGate';
import { detailLevel } from './detailLevel';
import { formatMoney } from './formatMoney';
import { selectionPath } from './selection';
import { usePlanGestures } from './usePlanGestures';
import { usePlanView } from './usePlanView';
import { type PlanPoint, type Viewport, fitRoom, worldToScreen } from './viewTransform';
import { systemBounds } from '../../core/model/geometry';
import { BottomBar } from './BottomBar';
import type { FootprintSource } from './footprintSource';
import { requestFootprints } from './moduleFootprint';
import { usePlannerKeys } from './usePlannerKeys';

export interface PlannerProps {
  store: ConfiguratorStore;
  ui: UiStore;
  locale?: string;
  /** Shows the room-setup screen again. */
  onNewRoom: () => void;
  /** Copies a share link; returns the message to show. */
  onShare: () => string;
  footprints: FootprintSource;
}

const ZOOM_STEP = 1.5;

/** The main screen (configurator paper, fig. 6): the plan, side panel with presets and price, bottom bar. */
export function Planner({ store, ui, locale, onNewRoom, onShare, footprints }: PlannerProps) {
  const config = useStore(store, (s) => s.config);
  const catalog = useStore(store, (s) => s.catalog);
  const selection = useStore(store, (s) => s.selection);
  const canUndo = useStore(store, (s) => s.canUndo);
  const canRedo = useStore(store, (s) => s.canRedo);
  const mode = useStore(ui, (s) => s.mode);
  const optionsOpen = useStore(ui, (s) => s.optionsOpen);
  const panelOpen = useStore(ui, (s) => s.panelOpen);
  const status = useStore(ui, (s) => s.status);
  const shareLink = useStore(ui, (s) => s.shareLink);

  const wrapRef = useRef<HTMLDivElement>(null);
  const [viewport, setViewport] = useState<Viewport>({ width: 800, height: 600 });
  const plan = usePlanView(fitRoom(config.room, viewport));
  const [drag, setDrag] = useState<{ systemId: string; delta: PlanPoint; invalid: boolean } | null>(null);

  const explain = useCallback((reason: string) => showStatus(ui, reason), [ui]);
  const run = useCallback(
    (name: string, params: unknown) => {
      const r = store.getState().dispatch(name, params);
      if (!r.ok) explain(r.reason);
    },
    [store, explain],
  );
  const gate = useMemo(() => createActionGate(config, catalog, run, explain), [config, catalog, run, explain]);
  const path = selectionPath(config, selection);
  const select = useCallback((sel: Selection) => store.getState().select(sel), [store]);
  const bom = useMemo(() => billOfMaterials(config, catalog), [config, catalog]);

  // Fit the room when the plan first gets its size and whenever the room's dimensions change.
  const roomKey = `${config.room.width}x${config.room.depth}`;
  const fittedFor = useRef<string | null>(null);
  const { jumpTo } = plan;
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
  useLayoutEffect(() => {
    const key = `${roomKey}@${viewport.width}x${viewport.height}`;
    if (fittedFor.current === key) return;
    fittedFor.current = key;
    jumpTo(fitRoom(config.room, viewport));
  }, [roomKey, viewport, config.room, jumpTo]);

  useEffect(() => {
    requestFootprints(footprints, config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)), catalog);
  }, [footprints, config, catalog]);

  // Status messages disappear after a few seconds (they explain, they do not block).
  useEffect(() => {
    if (!status) return;
    const t = window.setTimeout(() => ui.setState({ status: null }), 4000);
    return () => window.clearTimeout(t);
  }, [status, ui]);

  usePlanGestures(wrapRef, plan, {
    onSystemDrag: (systemId, delta) => {
      if (store.getState().selection?.id !== systemId) select({ kind: 'system', id: systemId });
      // Preview whether dropping here would be accepted (the model's isEnabled, live).
      const s = store.getState().config.systems.find((x) => x.id === systemId);
      const invalid = !s || store.getState().isEnabled('moveSystem', { systemId, x: s.x + delta.x, z: s.z + delta.z }) !== true;
      setDrag({ systemId, delta, invalid });
    },
    onSystemDrop: (systemId, delta) => {
      setDrag(null);
      const s = store.getState().config.systems.find((x) => x.id === systemId);
      if (!s) return;
      // Positions snap to whole centimetres so the move fields show clean numbers.
      const x = Math.round((s.x + delta.x) * 100) / 100;
      const z = Math.round((s.z + delta.z) * 100) / 100;
      run('moveSystem', { systemId, x, z });
    },
    onTap: (hit) => {
      if (!hit.systemId) {
        select(null);
        return;
      }
      // Like the controls, what a tap selects follows the zoom level: whole systems when zoomed
      // out, rails and modules when zoomed in.
      const zoomedIn = detailLevel(plan.targetRef.current.scale) === 'module';
      if (zoomedIn && hit.moduleId) select({ kind: 'module', id: hit.moduleId });
      else if (zoomedIn && hit.railId) select({ kind: 'rail', id: hit.railId });
      else select({ kind: 'system', id: hit.systemId });
    },
  });

  // Buttons and keys zoom about the selected system when it is on screen (so zooming in on it
  // reaches the module level without panning), else about the middle of the plan.
  const selectedSystem = config.systems.find((s) => s.id === path.systemId);
  const zoomButtons = useCallback(
    (factor: number) => {
      let anchor = { sx: viewport.width / 2, sy: viewport.height / 2 };
      if (selectedSystem) {
        const b = systemBounds(selectedSystem, catalog);
        const c = worldToScreen(plan.targetRef.current, { x: (b.minX + b.maxX) / 2, z: (b.minZ + b.maxZ) / 2 });
        if (c.sx >= 0 && c.sy >= 0 && c.sx <= viewport.width && c.sy <= viewport.height) anchor = c;
      }
      plan.zoomBy(factor, anchor);
    },
    [viewport, selectedSystem, catalog, plan],
  );
  const level = detailLevel(plan.view.scale);

  usePlannerKeys({ store, ui, run, explain, zoom: zoomButtons, enabled: mode === '2d' });

  const placedNew = () => {
    const systems = store.getState().config.systems;
    const last = systems[systems.length - 1];
    if (last) select({ kind: 'system', id: last.id });
    ui.setState({ panelOpen: false });
  };

  return (
    <div className="app-body">
      <div className="app-header">
        <h1>luxbox</h1>
        <span className="room-label">
          Room {config.room.width} × {config.room.depth} × {config.room.height} m
        </span>
        <span className="spacer" />
        <span className="total" data-testid="header-total" aria-label="Total price">
          {formatMoney(bom.total, bom.currency, locale)}
        </span>
        <button type="button" className="btn panel-toggle" aria-expanded={panelOpen} onClick={() => ui.setState({ panelOpen: !panelOpen })}>
          {panelOpen ? 'Close' : 'Presets'}
        </button>
      </div>
      <div className="workspace">
        <div className="stage">
          {mode === '2d' ? (
            <div className="plan-wrap" ref={wrapRef} data-testid="plan" data-scale={plan.view.scale.toFixed(3)} data-level={level}>
              <PlanSvg config={config} catalog={catalog} view={plan.view} selection={path} drag={drag} footprints={footprints} />
              <PlanControls
                config={config}
                catalog={catalog}
                view={plan.view}
                viewport={viewport}
                level={level}
                selection={path}
                gate={gate}
                onSelect={select}
                onOpenOptions={() => ui.setState({ optionsOpen: true, panelOpen: true })}
              />
              <div className="zoom-controls" data-plan-control>
                <ActionButton label="Zoom in" disabledReason={null} onPress={() => zoomButtons(ZOOM_STEP)} testId="zoom-in">
                  +
                </ActionButton>
                <ActionButton label="Zoom out" disabledReason={null} onPress={() => zoomButtons(1 / ZOOM_STEP)} testId="zoom-out">
                  −
                </ActionButton>
                <ActionButton label="Fit room" disabledReason={null} onPress={() => plan.animateTo(fitRoom(config.room, viewport))} testId="zoom-fit">
                  ⤢
                </ActionButton>
              </div>
              {status && (
                <div className="status-line" role="status" key={status.seq}>
                  {status.text}
                </div>
              )}
            </div>
          ) : (
            <LazyView3D store={store} onBack={() => ui.setState({ mode: '2d' })} />
          )}
          <BottomBar store={store} ui={ui} config={config} path={path} gate={gate} canUndo={canUndo} canRedo={canRedo} mode={mode} />
        </div>
        <aside className={`side-panel${panelOpen ? ' open' : ''}`} aria-label="Presets and price">
          {optionsOpen && <OptionsPanel config={config} catalog={catalog} path={path} gate={gate} onClose={() => ui.setState({ optionsOpen: false })} footprints={footprints} />}
          <PresetPanel catalog={catalog} gate={gate} onPlaced={placedNew} />
          <SurfacesPanel room={config.room} finishes={defaultSurfaceFinishes} gate={gate} />
          <BomPanel bom={bom} locale={locale} />
          <section className="panel-section">
            <div className="setup-actions">
              <button type="button" className="btn" onClick={() => explain(onShare())} data-testid="share">
                Share link
              </button>
              <button type="button" className="btn" onClick={onNewRoom}>
                New room
              </button>
            </div>
            <FilePanel store={store} ui={ui} />
            {shareLink && (
              <div className="field" style={{ marginTop: 8 }}>
                <label htmlFor="share-link">Link to this configuration</label>
                <input id="share-link" readOnly value={shareLink} onFocus={(e) => e.target.select()} data-testid="share-link" />
              </div>
            )}
          </section>
        </aside>
      </div>
    </div>
  );
}
