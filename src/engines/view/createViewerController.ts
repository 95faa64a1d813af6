import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { reflectanceRgb, type BakeScene } from '../bake/bakeScene';
import type { RelightEngine } from '../relight/RelightEngine';
import type { BakeService } from './createBakeService';
import { createCameraRig } from './createCameraRig';
import { createFrameScheduler } from './createFrameScheduler';
import { createMapDisplay, type MapsListener } from './createMapDisplay';
import { adoptedWhite } from './adoptedWhite';
import type { AdaptationSetting } from './adaptationSetting';
import { sceneGeometryKey } from './sceneGeometryKey';
import type { CameraPresetName } from './cameraPresets';
import type { Fixtures } from './fixtures';
import { applyLiveLevels } from './applyLiveLevels';
import type { LiveLevel } from './liveLevels';
import { createRoomView, type PickTarget, type RoomView, type ViewMode } from './roomView';
import { watchContextLoss } from './watchContextLoss';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { watchTaps } from './watchTaps';
import { litMapsOf, moduleWeightsOf } from './compareMaps';
import { objectLightOf } from './objectLight';
import { beamAndFieldDeg, createSpotlight, withoutModule, type SpotlightRequest } from './createSpotlight';
import type { ModuleAim } from '../../core/model/configuration/configuration';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';

/** The A/B compare (docs/viewer.md, "A/B compare"): two light scenes of the configuration, A left of the wipe at `split` (0…1 of the width), B right of it. */
export interface CompareRequest {
  a: BakeScene;
  b: BakeScene;
  split: number;
}

export interface ViewerEvents {
  /** Bake progress and counters changed. */
  onProgress(p: { fraction: number; done: boolean; lit: boolean; groupBakes: number; relightsOnly: number; indirectSolves: number }): void;
  /** New relit maps are on screen (for statistics and the legend). */
  onMaps: MapsListener;
  onFrame(frames: number): void;
  onContext(state: 'lost' | 'restored'): void;
  onError(message: string): void;
  /** A tap or click picked an object or a module (null: nothing, or only the room). */
  onPick?(target: PickTarget | null): void;
  /** A drag in the spotlight view ended on a new aim (docs/aiming.md): the host dispatches setAim. */
  onAim?(moduleId: string, aim: ModuleAim): void;
  /** In aim-at mode, a tap hit this world point of the room or an object: the host dispatches aimAt. */
  onAimAt?(point: Vec3): void;
}

/**
 * The imperative core of the 3D view (three.js, no React): renders on demand
 * only (createFrameScheduler), shows the maps of the bake service's engine
 * (createBakeService: it outlives the view, bakes in background slices and
 * relights instantly when only dimming or colour changed), survives WebGL
 * context loss. On creation it shows the engine's current maps at once: a view
 * opened again with nothing changed bakes nothing. Disposing it frees the
 * display (renderer, room view), never the service.
 */
export function createViewerController(canvas: HTMLCanvasElement, service: BakeService, events: ViewerEvents) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance' });
  renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
  let view: RoomView = createRoomView(renderer);
  /**
   * Veiling glare round bright sources in light mode (docs/viewer.md, "Glare"); lux mode never shows
   * it. Drawn once the configuration's light is done: while it bakes, frames come with every slice
   * and the pass's extra passes would take the bake's time on a slow GPU (a software renderer's
   * frames cost several times more with it).
   */
  let glare = true;
  let lightDone = false;
  const glareNow = () => glare && lightDone;
  const controls = new OrbitControls(view.camera, canvas);
  controls.enableDamping = false; // damping needs a continuous loop; we render on demand
  controls.screenSpacePanning = true;

  let scene: BakeScene | null = null;
  /** Module id per luminaire of `scene`, for the live overlay. */
  let ids: readonly string[] = [];
  /** Live control's levels over the scene's own dimming (transient: never in the configuration), or null. */
  let live: ReadonlyMap<string, LiveLevel> | null = null;
  /** The service lights the scene with the live overlay, if any (a relight: only dimming and colour change). */
  /** The module the spotlight view's preview lights from the shader while it is dragged (out of the relit maps), or null. */
  let dimmed: string | null = null;
  const applyOverlay = () =>
    service.setOverlay(
      live || dimmed
        ? (s: BakeScene) => {
            const levels = live ? applyLiveLevels(s, ids, live) : s;
            return dimmed ? withoutModule(levels, ids, dimmed) : levels;
          }
        : null,
    );
  /** Aim-at mode: the next tap aims the selected module at the point instead of picking. */
  let aimAt = false;
  /** The spotlight view the host asked for; shown once the scene has the module's luminaire (its beam and field come from its photometry). */
  let spotRequest: SpotlightRequest | null = null;
  const syncSpotlight = () => {
    const i = spotRequest ? ids.indexOf(spotRequest.moduleId) : -1;
    const l = i >= 0 ? scene?.luminaires[i] : undefined;
    spotlight.set(spotRequest && l ? { ...spotRequest, ...beamAndFieldDeg(l.photometry) } : null);
    frames.request();
  };
  let fixtures: Fixtures | null = null;
  /** The engine version on screen; -1 forces the next slice to show the maps. */
  let shownVersion = -1;
  /** The objects' geometry as the baker lays out their atlas (null: no objects; the service's), and the highlighted one. */
  let prepared: PreparedObjects | null = null;
  let selectedObject: string | null = null;
  let selectedModule: string | null = null;
  /** The A/B compare, or null; its B side is a second room view over the same renderer, camera pose and display uniforms. */
  let compare: CompareRequest | null = null;
  let compareView: RoomView | null = null;

  const display = watchContextLoss(canvas, {
    lost: () => events.onContext('lost'),
    restored() {
      // three re-creates its GL objects; rebuild the room so every texture and program is uploaded anew.
      view.dispose();
      compareView?.dispose();
      compareView = null;
      view = createRoomView(renderer);
      view.setGlare(glareNow());
      camera.attach(view);
      if (fixtures) view.setFixtures(fixtures);
      view.setRoomShape(scene?.room.shape ?? null);
      view.setObjects(prepared);
      view.setSelectedObject(selectedObject);
      view.setSelectedModule(selectedModule);
      spotlight.reattach();
      shownVersion = -1;
      if (service.engine) showMaps(service.engine);
      events.onContext('restored');
      frames.request();
    },
  });
  /** False while the view is kept but hidden (the 2D plan is on screen): no frames are drawn. */
  let active = true;
  const frames = createFrameScheduler({
    draw: () => {
      // The eye adapting after a cut or a Re-adapt: one more frame while it moves (eyeAdaptation.ts).
      if (maps.advance(performance.now())) frames.request();
      view.render(renderer);
      if (compare && compareView) drawCompare(compare, compareView);
    },
    canDraw: () => active && !display.lost,
    onFrame: events.onFrame,
  });
  controls.addEventListener('change', frames.request);
  const camera = createCameraRig(controls, view);
  const stopTaps = watchTaps(canvas, (x, y) => {
    if (aimAt) {
      const point = view.pickPoint(x, y);
      if (point) events.onAimAt?.(point);
      return;
    }
    // In the spotlight view a tap ends a drag of the head; it selects nothing.
    if (!spotlight.active()) events.onPick?.(view.pick(x, y));
  });
  const spotlight = createSpotlight({
    canvas,
    view: () => view,
    controls,
    request: () => frames.request(),
    room: () => scene?.room ?? null,
    lamp(moduleId) {
      const i = ids.indexOf(moduleId);
      const l = i >= 0 ? scene?.luminaires[i] : undefined;
      if (!l) return null;
      const d = Math.max(0, l.dimming ?? 1);
      const c = l.color ?? [1, 1, 1];
      return { photometry: l.photometry, weight: [d * c[0], d * c[1], d * c[2]] };
    },
    setDimmed(moduleId) {
      if (moduleId === dimmed) return;
      dimmed = moduleId;
      if (scene) applyOverlay();
    },
    onAim: (moduleId, aim) => events.onAim?.(moduleId, aim),
    linearFloat: renderer.extensions.has('OES_texture_float_linear'),
  });
  const maps = createMapDisplay(() => view, events.onMaps);

  /**
   * The glow follows the light shown (dimming, live levels, a crossfade's mix: the service's
   * weights), except the module the spotlight preview lights from the shader: the maps leave it
   * out, its lamp still shines (its weight with the live levels).
   */
  const syncWeights = () => {
    // During the A/B compare each side shows its own scene's glow (showCompare).
    if (compare) return;
    const weights = service.luminaireWeights();
    if (!weights || !scene || service.scene !== scene) return;
    const k = dimmed ? ids.indexOf(dimmed) : -1;
    const own = k >= 0 ? (live ? applyLiveLevels(scene, ids, live) : scene).luminaires[k] : undefined;
    if (own) {
      const d = Math.max(0, own.dimming ?? 1);
      const c = own.color ?? [1, 1, 1];
      weights[k] = [d * c[0], d * c[1], d * c[2]];
    }
    view.setModuleWeights(new Map(weights.flatMap((w, i) => (ids[i] ? [[ids[i], w] as const] : []))));
  };
  /** Both sides' maps from the engine (relights, no bake): A on the main view, B on the compare view; the exposure and adaptation stay the held ones. */
  const showCompare = (engine: RelightEngine, request: CompareRequest) => {
    const lit = litMapsOf(engine, [request.a, request.b]);
    if (!lit || !scene) return false;
    const reflectance = reflectanceRgb(scene.room);
    if (!compareView) {
      compareView = createRoomView(renderer);
      compareView.setGlare(glareNow());
      if (fixtures) compareView.setFixtures(fixtures);
      compareView.setRoomShape(scene.room.shape ?? null);
      compareView.setObjects(prepared);
    }
    const sides: [RoomView, BakeScene][] = [
      [view, request.a],
      [compareView, request.b],
    ];
    sides.forEach(([v, s], k) => {
      v.setMaps(lit[k], reflectance);
      v.setObjectLight(objectLightOf(lit[k]));
      v.setModuleWeights(moduleWeightsOf(s, ids));
    });
    return true;
  };
  /** B over the part of the canvas right of the wipe: same camera, same exposure, adaptation and mode as A. */
  const drawCompare = (request: CompareRequest, b: RoomView) => {
    const from = view.display;
    const to = b.display;
    to.uExposure.value = from.uExposure.value;
    to.uAdapt.value.copy(from.uAdapt.value);
    to.uMode.value = from.uMode.value;
    to.uLevelCount.value = from.uLevelCount.value;
    from.uLevels.value.forEach((v, i) => (to.uLevels.value[i] = v));
    b.camera.copy(view.camera);
    b.camera.updateMatrixWorld();
    const { width, height } = camera.size;
    const x = Math.round(Math.min(1, Math.max(0, request.split)) * width);
    renderer.setScissor(x, 0, width - x, height);
    renderer.setScissorTest(true);
    b.render(renderer);
    renderer.setScissorTest(false);
  };
  const showMaps = (engine: RelightEngine) => {
    if (!scene) return;
    lightDone = engine.progress.done;
    view.setGlare(glareNow());
    compareView?.setGlare(glareNow());
    if (compare && showCompare(engine, compare)) {
      shownVersion = engine.version;
      frames.request();
      return;
    }
    const t0 = performance.now();
    maps.show(engine.maps(), reflectanceRgb(scene.room), t0, { white: adoptedWhite(scene.luminaires), key: sceneGeometryKey(scene), done: engine.progress.done });
    syncWeights();
    shownVersion = engine.version;
    frames.request();
  };

  const counters = () => {
    const { groupBakes, relightsOnly, indirectSolves } = service.status();
    return { groupBakes, relightsOnly, indirectSolves };
  };
  /** The service's objects layout on screen (it changes with the objects and with the quality's texel size). */
  const syncObjects = () => {
    const next = service.objects();
    if (next === prepared) return;
    // New or moved objects: their old light belongs to another atlas; they show again with the new bake's first maps.
    prepared = next;
    view.setObjects(prepared);
    compareView?.setObjects(prepared);
    shownVersion = -1;
  };
  const unsubscribe = service.subscribe((e) => {
    if (e.type === 'slice') {
      const p = e.progress;
      if (e.engine.version !== shownVersion && (p.lit || p.done)) showMaps(e.engine);
      else if (p.done !== lightDone) {
        // Done (or baking again) without new maps: the glare follows.
        lightDone = p.done;
        view.setGlare(glareNow());
        compareView?.setGlare(glareNow());
        frames.request();
      }
      spotlight.bakeProgress(p.done);
      events.onProgress({ fraction: p.fraction, done: p.done, lit: p.lit, ...counters() });
    } else if (e.type === 'engine') {
      shownVersion = -1;
      syncObjects();
    } else if (e.type === 'context') events.onContext(e.state);
    else if (e.type === 'error') events.onError(e.message);
  });
  if (service.error) queueMicrotask(() => events.onError(service.error!));

  return {
    /** A new scene (any change of the configuration): bakes only new or moved groups, relights the rest. */
    setScene(next: BakeScene, nextFixtures: Fixtures, luminaireIds: readonly string[] = []) {
      scene = next;
      ids = luminaireIds;
      fixtures = nextFixtures;
      view.setFixtures(nextFixtures);
      compareView?.setFixtures(nextFixtures);
      view.setRoomShape(next.room.shape ?? null);
      compareView?.setRoomShape(next.room.shape ?? null);
      syncWeights();
      syncObjects();
      camera.setScene(next);
      if (live || dimmed) applyOverlay();
      spotlight.sceneChanged();
      if (spotRequest) syncSpotlight();
      // The engine's maps for this scene, at once when it has them (a view opened again after no change: no bake, no wait).
      const engine = service.engine;
      if (engine && service.scene === next) {
        const p = engine.progress;
        if (engine.version !== shownVersion && (p.lit || p.done)) showMaps(engine);
        events.onProgress({ fraction: p.fraction, done: p.done, lit: p.lit, ...counters() });
      }
      frames.request();
    },
    /**
     * Live control's levels over the configuration's dimming (null: the configuration's own
     * again). Only dimming and colour change, so it is a relight, never a bake.
     */
    setLiveLevels(levels: ReadonlyMap<string, LiveLevel> | null) {
      live = levels;
      if (!scene) return;
      applyOverlay();
    },
    setExposureEv(ev: number) {
      maps.setExposureEv(ev);
      frames.request();
    },
    /** Absolute exposure in EV100 (photographicExposure.ts), or null: automatic exposure again. */
    setEv100(ev100: number | null) {
      maps.setEv100(ev100);
      frames.request();
    },
    /** EV100 of the exposure on screen now: "lock exposure" passes it to setEv100. */
    currentEv100(): number {
      return maps.currentEv100();
    },
    /** Chromatic adaptation: eye (default), camera white balance at a CCT, none (chromaticAdaptation.ts). */
    setAdaptation(setting: AdaptationSetting) {
      maps.setAdaptation(setting);
      frames.request();
    },
    /** Adapt the automatic exposure and white to the light on screen now (they hold while the light is only dimmed or recoloured). */
    reAdapt() {
      maps.reAdapt();
      frames.request();
    },
    /** Whether the automatic exposure is held (relights keep it; a new room, a camera preset or reAdapt adapt again). */
    exposureHeld(): boolean {
      return maps.held();
    },
    setMode(m: ViewMode) {
      maps.setMode(m);
      frames.request();
    },
    /** Veiling glare on or off (light mode only). */
    setGlare(on: boolean) {
      glare = on;
      view.setGlare(glareNow());
      compareView?.setGlare(glareNow());
      frames.request();
    },
    /**
     * The A/B compare of two light scenes (same luminaires as the scene, other dimming and colour),
     * or null to end it: A left of the wipe, B right, both at the exposure and adaptation held now.
     */
    setCompare(request: CompareRequest | null) {
      const scenesChanged = !compare || !request || compare.a !== request.a || compare.b !== request.b;
      compare = request;
      if (!request) {
        compareView?.dispose();
        compareView = null;
      }
      if (scenesChanged) {
        shownVersion = -1;
        const engine = service.engine;
        if (engine && (engine.progress.lit || engine.progress.done)) showMaps(engine);
        if (!request) syncWeights();
      }
      frames.request();
    },
    /** The compare drawn last: both sides' exposures (the same by construction) and the wipe, or null. */
    compareState(): { exposureA: number; exposureB: number; split: number } | null {
      if (!compare || !compareView) return null;
      return { exposureA: view.display.uExposure.value, exposureB: compareView.display.uExposure.value, split: compare.split };
    },
    /** Whether the last frame went through the glare pass (light mode on a renderer with half-float targets). */
    glareShown(): boolean {
      return view.glareShown();
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
    /**
     * The spotlight view of an adjustable module (docs/aiming.md), following its aim as the store
     * changes it; null leaves it (the orbit camera comes back where it was).
     */
    setSpotlight(target: SpotlightRequest | null) {
      spotRequest = target;
      syncSpotlight();
    },
    /** Aim-at mode: the next taps report world points (onAimAt) instead of picking. */
    setAimAt(on: boolean) {
      aimAt = on;
    },
    setPreset(name: CameraPresetName) {
      camera.setPreset(name);
      // A camera cut: the eye adapts to the room again.
      maps.reAdapt();
      frames.request();
    },
    resize(width: number, height: number) {
      camera.resize(width, height);
      renderer.setSize(camera.size.width, camera.size.height, false);
      frames.request();
    },
    /**
     * Shown or hidden without being disposed (the planner keeps the view while the 2D plan is on
     * screen, so the next 2D → 3D toggle costs one frame): hidden, nothing is drawn; shown again,
     * one frame with the maps it holds.
     */
    setActive(next: boolean) {
      active = next;
      if (active) frames.request();
    },
    /** Frees the display only: the service keeps its engine, maps and pending work. */
    dispose() {
      compareView?.dispose();
      unsubscribe();
      if (live) service.setOverlay(null);
      frames.stop();
      stopTaps();
      spotlight.dispose();
      controls.dispose();
      view.dispose();
      renderer.dispose();
      display.dispose();
    },
  };
}

export type ViewerController = ReturnType<typeof createViewerController>;
