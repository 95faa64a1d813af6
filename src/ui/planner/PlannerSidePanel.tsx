import { lazy, Suspense, useEffect } from 'react';
import type { MeshUnits } from '../../core/model/configuration/configuration';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import { defaultSurfaceFinishes } from '../../core/catalog/surfaceFinishes';
import { noticeText } from '../i18n/noticeText';
import { LazyScenePanel as ScenePanel } from '../scenes/LazyScenePanel';
import { aimAtMode } from '../shared/aimAtMode';
import { addImportedModel, addLibraryItem } from './addFurniture';
import { BomPanel } from './BomPanel';
import { FilePanel } from './FilePanel';
import { FurniturePanel } from './FurniturePanel';
import { LazyImportPanel } from './LazyImportPanel';
import { LazyOptionsPanel as OptionsPanel } from './LazyOptionsPanel';
import type { PlannerScope } from './plannerScope';
import { PresetPanel } from './PresetPanel';
import { SurfacesPanel } from './SurfacesPanel';
import { LazyDaylightSection } from './LazyDaylightSection';

// The share link's copy and share buttons load once a link is made (not with the first screen).
const ShareLinkField = lazy(() => import('./ShareLinkField'));
// The Expert switch loads only where the shop offers it (docs/embedding.md, option `expert`).
const ExpertSwitch = lazy(() => import('./ExpertSwitch'));

/** The side panel (a drawer on narrow boxes): options of the selection, presets, furniture, scenes, surfaces, the bill, files and sharing. */
export function PlannerSidePanel({ p }: { p: PlannerScope }) {
  const { store, ui, controller, config, catalog, gate, path, footprints, t, language, optionsOpen, panelOpen, expert, panelRef, selection } = p;
  const explain = controller.explain;
  // The options sit at the top of the side panel: show them when they open, wherever the panel was scrolled to (the furniture list, say).
  useEffect(() => {
    if (optionsOpen && panelRef.current) panelRef.current.scrollTop = 0;
  }, [optionsOpen, selection, panelRef]);
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
  return (
    <aside ref={panelRef} className={`side-panel${panelOpen ? ' open' : ''}`} aria-label={t('planner.sidePanel')}>
      {/* A module's photometric data notes are an expert tool: without the loader the options show none. */}
      {optionsOpen && <OptionsPanel config={config} catalog={catalog} path={path} gate={gate} onClose={() => ui.setState({ optionsOpen: false })} footprints={expert ? footprints : undefined} aimMode={aimAtMode(store)} />}
      <PresetPanel
        catalog={catalog}
        gate={gate}
        onPlaced={p.placedNew}
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
      <LazyDaylightSection config={config} gate={gate} lightSources={{ value: p.lightSources, set: (lightSources) => p.ui.setState({ lightSources }) }} />
      <BomPanel bom={p.bom} needs={p.needs} catalog={catalog} />
      <section className="panel-section">
        <div className="setup-actions">
          <button type="button" className="btn" onClick={() => explain(p.onShare())} data-testid="share">
            {t('planner.shareLink')}
          </button>
          <button type="button" className="btn" onClick={p.onNewRoom}>
            {t('planner.newRoom')}
          </button>
        </div>
        <FilePanel store={store} ui={ui} loadPhotometry={footprints.loadPhotometry} />
        {p.expertSwitch && (
          <Suspense fallback={null}>
            <ExpertSwitch ui={ui} />
          </Suspense>
        )}
        {p.shareLink && (
          <Suspense fallback={null}>
            <ShareLinkField link={p.shareLink} notice={p.shareNotice ?? null} />
          </Suspense>
        )}
      </section>
    </aside>
  );
}
