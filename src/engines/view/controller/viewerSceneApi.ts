import type { BakeScene } from '../../bake/bakeScene';
import type { PreparedObjects } from '../../bake/objects/preparedObjects';
import type { SpotlightRequest } from '../createSpotlight';
import type { Fixtures } from '../fixtures';
import type { LiveLevel } from '../liveLevels';
import { bakeCounters, showMaps, syncObjects, syncWeights } from './showViewerMaps';
import { applyOverlay, syncSpotlight } from './viewerOverlay';
import type { Viewer } from './viewer';

/** The windows of the scene on screen: its daylight unless the view shows electric light only (then, as without daylight, the night sky). */
export function syncWindows(v: Viewer): void {
  const scene = v.scene;
  const daylight = scene?.daylight && v.service.lightSources !== 'electric' ? scene.daylight : null;
  v.view.setWindows(scene?.room.shape ?? null, daylight, scene?.daylight?.glazing ?? new Map());
  v.frames.request();
}

/** The viewer controller's methods for what is shown: the scene, live levels, selection, the spotlight view, aim-at. */
export function viewerSceneApi(v: Viewer) {
  return {
    /** A new scene (any change of the configuration): bakes only new or moved groups, relights the rest. */
    setScene(next: BakeScene, nextFixtures: Fixtures, luminaireIds: readonly string[] = []) {
      v.scene = next;
      v.ids = luminaireIds;
      v.fixtures = nextFixtures;
      v.view.setFixtures(nextFixtures);
      v.compareView?.setFixtures(nextFixtures);
      v.view.setRoomShape(next.room.shape ?? null);
      v.compareView?.setRoomShape(next.room.shape ?? null);
      syncWindows(v);
      syncWeights(v);
      syncObjects(v);
      v.camera.setScene(next);
      if (v.live || v.dimmed) applyOverlay(v);
      v.spotlight.sceneChanged();
      if (v.spotRequest) syncSpotlight(v);
      // The engine's maps for this scene, at once when it has them (a view opened again after no change: no bake, no wait).
      const engine = v.service.engine;
      if (engine && v.service.scene === next) {
        const p = engine.progress;
        if (engine.version !== v.shownVersion && (p.lit || p.done)) showMaps(v, engine);
        v.events.onProgress({ fraction: p.fraction, done: p.done, lit: p.lit, ...bakeCounters(v) });
      }
      v.frames.request();
    },
    /**
     * Live control's levels over the configuration's dimming (null: the configuration's own
     * again). Only dimming and colour change, so it is a relight, never a bake.
     */
    setLiveLevels(levels: ReadonlyMap<string, LiveLevel> | null) {
      v.live = levels;
      if (!v.scene) return;
      applyOverlay(v);
    },
    /** The objects' geometry on screen, as the baker lays out their atlas (null: no objects). */
    objects(): PreparedObjects | null {
      return v.prepared;
    },
    /** Highlight the store's selection when it is an object or a module (null: none). */
    setSelection(selection: { kind: string; id: string } | null) {
      v.selectedObject = selection?.kind === 'object' ? selection.id : null;
      v.selectedModule = selection?.kind === 'module' ? selection.id : null;
      v.view.setSelectedObject(v.selectedObject);
      v.view.setSelectedModule(v.selectedModule);
      v.frames.request();
    },
    /**
     * The spotlight view of an adjustable module (docs/aiming.md), following its aim as the store
     * changes it; null leaves it (the orbit camera comes back where it was).
     */
    setSpotlight(target: SpotlightRequest | null) {
      v.spotRequest = target;
      syncSpotlight(v);
    },
    /** Aim-at mode: the next taps report world points (onAimAt) instead of picking. */
    setAimAt(on: boolean) {
      v.aimAt = on;
    },
  };
}
