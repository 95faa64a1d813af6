import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { reflectanceRgb, type BakeScene } from '../bake/bakeScene';
import type { EngineProgress, RelightEngine } from '../relight/createRelightEngine';
import { createBakeContext } from './createBakeContext';
import { createBakeSlicer } from './createBakeSlicer';
import { createCameraRig } from './createCameraRig';
import { createFrameScheduler } from './createFrameScheduler';
import { createMapDisplay, type MapsListener } from './createMapDisplay';
import type { CameraPresetName } from './cameraPresets';
import type { Fixtures } from './fixtures';
import { applyLiveLevels } from './applyLiveLevels';
import type { LiveLevel } from './liveLevels';
import { createRoomView, type PickTarget, type RoomView, type ViewMode } from './roomView';
import { watchContextLoss } from './watchContextLoss';
import { resolveBakeSettings } from '../bake/bakeSettings';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { VIEWER_BAKE_SETTINGS } from '../relight/createRelightEngine';
import { createObjectsMemo } from './createObjectsMemo';
import { watchTaps } from './watchTaps';

export interface ViewerEvents {
  /** Bake progress and counters changed. */
  onProgress(p: { fraction: number; done: boolean; lit: boolean; groupBakes: number; relightsOnly: number }): void;
  /** New relit maps are on screen (for statistics and the legend). */
  onMaps: MapsListener;
  onFrame(frames: number): void;
  onContext(state: 'lost' | 'restored'): void;
  onError(message: string): void;
  /** A tap or click picked an object or a module (null: nothing, or only the room). */
  onPick?(target: PickTarget | null): void;
}

/**
 * The imperative core of the 3D view (three.js, no React): renders on demand
 * only (createFrameScheduler), bakes in background slices between frames
 * (createBakeSlicer), relights instantly when only dimming or colour changed,
 * survives WebGL context loss. The baker has its own WebGL2 context
 * (createBakeContext): its basis maps live on the CPU, so losing the display
 * context costs a re-upload, and losing the bake context costs a rebake once
 * it is restored. This file wires those parts to the scene and the room view.
 */
export function createViewerController(canvas: HTMLCanvasElement, events: ViewerEvents) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance' });
  renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
  let view: RoomView = createRoomView(renderer);
  const controls = new OrbitControls(view.camera, canvas);
  controls.enableDamping = false; // damping needs a continuous loop; we render on demand
  controls.screenSpacePanning = true;

  let scene: BakeScene | null = null;
  /** Module id per luminaire of `scene`, for the live overlay. */
  let ids: readonly string[] = [];
  /** Live control's levels over the scene's own dimming (transient: never in the configuration), or null. */
  let live: ReadonlyMap<string, LiveLevel> | null = null;
  /** What the engine lights: the scene with the live overlay, if any. */
  const lit = (s: BakeScene): BakeScene => (live ? applyLiveLevels(s, ids, live) : s);
  let fixtures: Fixtures | null = null;
  /** The engine version on screen; -1 forces the next slice to show the maps. */
  let shownVersion = -1;
  /** The objects' geometry as the baker lays out their atlas (null: no objects), and the highlighted one. */
  const prepareFor = createObjectsMemo();
  let prepared: PreparedObjects | null = null;
  let selectedObject: string | null = null;
  let selectedModule: string | null = null;

  const display = watchContextLoss(canvas, {
    lost: () => events.onContext('lost'),
    restored() {
      // three re-creates its GL objects; rebuild the room so every texture and program is uploaded anew.
      view.dispose();
      view = createRoomView(renderer);
      camera.attach(view);
      if (fixtures) view.setFixtures(fixtures);
      view.setObjects(prepared);
      view.setSelectedObject(selectedObject);
      view.setSelectedModule(selectedModule);
      shownVersion = -1;
      if (bake.engine) showMaps(bake.engine);
      events.onContext('restored');
      frames.request();
    },
  });
  const frames = createFrameScheduler({ draw: () => view.render(renderer), canDraw: () => !display.lost, onFrame: events.onFrame });
  controls.addEventListener('change', frames.request);
  const camera = createCameraRig(controls, view);
  const stopTaps = watchTaps(canvas, (x, y) => events.onPick?.(view.pick(x, y)));
  const maps = createMapDisplay(() => view, events.onMaps);

  const showMaps = (engine: RelightEngine) => {
    if (!scene) return;
    const t0 = performance.now();
    maps.show(engine.maps(), reflectanceRgb(scene.room), t0);
    shownVersion = engine.version;
    frames.request();
  };

  const bake = createBakeContext({
    onLost: () => events.onContext('lost'),
    onRestored(engine) {
      if (engine && scene) engine.setScene(lit(scene));
      shownVersion = -1;
      events.onContext('restored');
      slicer.queue();
    },
    onError: events.onError,
  });
  const slicer = createBakeSlicer({
    engine: () => bake.engine,
    onSlice(engine: RelightEngine, p: EngineProgress) {
      if (engine.version !== shownVersion && (p.lit || p.done)) showMaps(engine);
      events.onProgress({ fraction: p.fraction, done: p.done, lit: p.lit, ...bake.counters() });
    },
    onError: events.onError,
  });

  return {
    /** A new scene (any change of the configuration): bakes only new or moved groups, relights the rest. */
    setScene(next: BakeScene, nextFixtures: Fixtures, luminaireIds: readonly string[] = []) {
      scene = next;
      ids = luminaireIds;
      fixtures = nextFixtures;
      view.setFixtures(nextFixtures);
      const nextPrepared = prepareFor(next.objects, bake.engine?.settings ?? resolveBakeSettings(VIEWER_BAKE_SETTINGS));
      if (nextPrepared !== prepared) {
        // New or moved objects: their old light belongs to another atlas; they show again with the new bake's first maps.
        prepared = nextPrepared;
        view.setObjects(prepared);
        shownVersion = -1;
      }
      camera.setRoom(next.room);
      bake.engine?.setScene(lit(next));
      frames.request();
      slicer.run();
    },
    /**
     * Live control's levels over the configuration's dimming (null: the configuration's own
     * again). Only dimming and colour change, so it is a relight, never a bake.
     */
    setLiveLevels(levels: ReadonlyMap<string, LiveLevel> | null) {
      live = levels;
      if (!scene) return;
      bake.engine?.setScene(lit(scene));
      slicer.run();
    },
    setExposureEv(ev: number) {
      maps.setExposureEv(ev);
      frames.request();
    },
    setMode(m: ViewMode) {
      maps.setMode(m);
      frames.request();
    },
    /** The objects' geometry on screen, as the baker lays out their atlas (null: no objects). */
    objects(): PreparedObjects | null {
      return prepared;
    },
    /** Highlight the store's selection when it is an object or a module (null: none). */
    setSelection(selection: { kind: string; id: string } | null) {
      selectedObject = selection?.kind === 'object' ? selection.id : null;
      selectedModule = selection?.kind === 'module' ? selection.id : null;
      view.setSelectedObject(selectedObject);
      view.setSelectedModule(selectedModule);
      frames.request();
    },
    setPreset(name: CameraPresetName) {
      camera.setPreset(name);
      frames.request();
    },
    resize(width: number, height: number) {
      camera.resize(width, height);
      renderer.setSize(camera.size.width, camera.size.height, false);
      frames.request();
    },
    dispose() {
      frames.stop();
      slicer.stop();
      stopTaps();
      controls.dispose();
      view.dispose();
      bake.dispose();
      renderer.dispose();
      display.dispose();
    },
  };
}

export type ViewerController = ReturnType<typeof createViewerController>;
