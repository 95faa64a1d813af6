import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { toRgb, type BakeScene } from '../bake/bakeScene';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene';
import { createRelightEngine, type RelightEngine } from '../relight/createRelightEngine';
import type { LitMaps } from '../relight/relightMaps';
import { autoExposure } from './autoExposure';
import { cameraPreset, type CameraPresetName } from './cameraPresets';
import { luxLevels } from './falseColorScale';
import { luxScaleTop } from './luxScaleTop';
import type { Fixtures } from './fixtures';
import { createRoomView, type RoomView, type ViewMode } from './roomView';

export interface ViewerEvents {
  /** Bake progress and counters changed. */
  onProgress(p: { fraction: number; done: boolean; lit: boolean; groupBakes: number; relightsOnly: number }): void;
  /** New relit maps are on screen (for statistics and the legend). */
  onMaps(lit: LitMaps, info: { exposure: number; levels: number[]; relightMs: number }): void;
  onFrame(frames: number): void;
  onContext(state: 'lost' | 'restored'): void;
  onError(message: string): void;
}

/** Milliseconds of bake work per slice: keeps a 60 Hz frame for interaction in between. */
const SLICE_MS = 12;
/** Starting guess of the cost of one indirect sample per texel (all six maps), refined as it runs. */
const FIRST_MS_PER_SAMPLE = 1.5;

/**
 * The imperative core of the 3D view (three.js, no React): renders on demand
 * only (orbit changes, new maps, settings), bakes in background slices between
 * frames, relights instantly when only dimming or colour changed, survives
 * WebGL context loss. The baker has its own WebGL2 context: its basis maps
 * live on the CPU, so losing the display context costs a re-upload, and
 * losing the bake context costs a rebake once it is restored.
 */
export function createViewerController(canvas: HTMLCanvasElement, events: ViewerEvents) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance' });
  renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
  let view: RoomView = createRoomView(renderer);
  const controls = new OrbitControls(view.camera, canvas);
  controls.enableDamping = false; // damping needs a continuous loop; we render on demand
  controls.screenSpacePanning = true;

  let bakeCanvas = document.createElement('canvas');
  const carried = { groupBakes: 0, relightsOnly: 0 };
  let engine: RelightEngine | null = null;
  let scene: BakeScene | null = null;
  let fixtures: Fixtures | null = null;
  let reflectance: Record<SurfaceName, Rgb> | null = null;
  let shownVersion = -1;
  let exposureEv = 0;
  let autoValue = 1;
  let mode: ViewMode = 'light';
  let levels: number[] = [1];
  let frames = 0;
  let frameQueued = false;
  let workQueued = false;
  let displayLost = false;
  let bakeLost = false;
  let disposed = false;
  let lastLit: LitMaps | null = null;
  let size = { width: 1, height: 1 };
  let preset: CameraPresetName = 'corner';
  let msPerSample = FIRST_MS_PER_SAMPLE;

  const makeEngine = (): RelightEngine | null => {
    const gl = bakeCanvas.getContext('webgl2');
    if (!gl) {
      events.onError('Could not create a WebGL2 context for baking the light.');
      return null;
    }
    try {
      return createRelightEngine(gl);
    } catch (e) {
      events.onError(`The light baker cannot run on this device: ${(e as Error).message}`);
      return null;
    }
  };

  const onBakeLost = (e: Event) => {
    e.preventDefault();
    bakeLost = true;
    if (engine) {
      // Counters run on across engines, so hosts see the rebake as more group bakes.
      carried.groupBakes += engine.counters.groupBakes;
      carried.relightsOnly += engine.counters.relightsOnly;
    }
    engine = null; // its GPU objects are gone; the CPU basis maps go with it, and we rebake
    events.onContext('lost');
  };
  const onBakeRestored = () => {
    bakeLost = false;
    // A fresh canvas gives a fresh context object, so no stale compiled programs are reused.
    bakeCanvas.removeEventListener('webglcontextlost', onBakeLost);
    bakeCanvas.removeEventListener('webglcontextrestored', onBakeRestored);
    bakeCanvas = document.createElement('canvas');
    listenBake();
    engine = makeEngine();
    if (engine && scene) engine.setScene(scene);
    shownVersion = -1;
    events.onContext('restored');
    queueWork();
  };
  const listenBake = () => {
    bakeCanvas.addEventListener('webglcontextlost', onBakeLost);
    bakeCanvas.addEventListener('webglcontextrestored', onBakeRestored);
  };
  listenBake();
  engine = makeEngine();

  const renderNow = () => {
    frameQueued = false;
    if (disposed || displayLost) return;
    view.render(renderer);
    frames++;
    events.onFrame(frames);
  };
  const requestRender = () => {
    if (frameQueued || disposed) return;
    frameQueued = true;
    requestAnimationFrame(renderNow);
  };
  controls.addEventListener('change', requestRender);

  const levelsFor = (lit: LitMaps) => luxLevels(luxScaleTop(lit));

  const showMaps = () => {
    if (!engine || !reflectance) return;
    const t0 = performance.now();
    const lit = engine.maps();
    view.setMaps(lit, reflectance);
    autoValue = autoExposure(lit, reflectance);
    view.setExposure(autoValue * 2 ** exposureEv);
    levels = levelsFor(lit);
    view.setMode(mode, levels);
    lastLit = lit;
    shownVersion = engine.version;
    events.onMaps(lit, { exposure: autoValue * 2 ** exposureEv, levels, relightMs: performance.now() - t0 });
    requestRender();
  };

  const work = () => {
    workQueued = false;
    if (disposed || !engine || bakeLost) return;
    const start = performance.now();
    let p = engine.progress;
    try {
      while (!p.done && performance.now() - start < SLICE_MS) {
        // As many samples as fit the slice on this device (measured), so a slow GPU still yields to input.
        const n = Math.max(1, Math.min(engine.settings.samplesPerDraw, Math.floor(SLICE_MS / msPerSample)));
        const t = performance.now();
        p = engine.step(n);
        msPerSample = 0.7 * msPerSample + (0.3 * (performance.now() - t)) / n;
      }
    } catch (e) {
      events.onError(`Baking failed: ${(e as Error).message}`);
      return;
    }
    if (engine.version !== shownVersion && (p.lit || p.done)) showMaps();
    const c = engine.counters;
    events.onProgress({ fraction: p.fraction, done: p.done, lit: p.lit, groupBakes: carried.groupBakes + c.groupBakes, relightsOnly: carried.relightsOnly + c.relightsOnly });
    if (!p.done) queueWork();
  };
  // setTimeout, not requestAnimationFrame: baking continues in a background tab's budget too, and frames stay free for input.
  const queueWork = () => {
    if (workQueued || disposed) return;
    workQueued = true;
    setTimeout(work, 0);
  };

  const onDisplayLost = (e: Event) => {
    e.preventDefault();
    displayLost = true;
    events.onContext('lost');
  };
  const onDisplayRestored = () => {
    displayLost = false;
    // three re-creates its GL objects; rebuild the room so every texture and program is uploaded anew.
    view.dispose();
    view = createRoomView(renderer);
    controls.object = view.camera;
    applyPose(false);
    if (fixtures) view.setFixtures(fixtures);
    shownVersion = -1;
    if (engine) showMaps();
    events.onContext('restored');
    requestRender();
  };
  canvas.addEventListener('webglcontextlost', onDisplayLost);
  canvas.addEventListener('webglcontextrestored', onDisplayRestored);

  let pose = { position: view.camera.position.clone(), target: new THREE.Vector3() };
  const applyPose = (fromPreset: boolean) => {
    if (!scene) return;
    if (fromPreset) {
      const p = cameraPreset(preset, scene.room);
      const aspect = size.width / size.height;
      if (preset !== 'eye' && aspect < 1) {
        // Presets frame the room for a landscape view; on a portrait screen step back so its width still fits.
        const k = 1 / aspect;
        p.position = p.position.map((v, i) => p.target[i] + (v - p.target[i]) * k) as typeof p.position;
      }
      pose = { position: new THREE.Vector3(...p.position), target: new THREE.Vector3(...p.target) };
      view.setCamera(p, size.width / size.height);
    } else {
      view.camera.aspect = size.width / size.height;
      view.camera.position.copy(pose.position);
      view.camera.updateProjectionMatrix();
    }
    controls.target.copy(pose.target);
    controls.update();
  };
  controls.addEventListener('end', () => {
    pose = { position: view.camera.position.clone(), target: controls.target.clone() };
  });

  let roomKey = '';
  return {
    /** A new scene (any change of the configuration): bakes only new or moved groups, relights the rest. */
    setScene(next: BakeScene, nextFixtures: Fixtures) {
      const key = JSON.stringify([next.room.width, next.room.height, next.room.depth]);
      scene = next;
      fixtures = nextFixtures;
      reflectance = Object.fromEntries(SURFACE_NAMES.map((n) => [n, toRgb(next.room.reflectance[n])])) as Record<SurfaceName, Rgb>;
      view.setFixtures(nextFixtures);
      if (key !== roomKey) {
        roomKey = key;
        applyPose(true);
      }
      if (engine) engine.setScene(next);
      requestRender();
      work();
    },
    setExposureEv(ev: number) {
      exposureEv = ev;
      view.setExposure(autoValue * 2 ** ev);
      if (lastLit) events.onMaps(lastLit, { exposure: autoValue * 2 ** ev, levels, relightMs: 0 });
      requestRender();
    },
    setMode(m: ViewMode) {
      mode = m;
      view.setMode(m, levels);
      requestRender();
    },
    setPreset(name: CameraPresetName) {
      preset = name;
      applyPose(true);
      requestRender();
    },
    resize(width: number, height: number) {
      size = { width: Math.max(1, width), height: Math.max(1, height) };
      renderer.setSize(size.width, size.height, false);
      view.camera.aspect = size.width / size.height;
      view.camera.updateProjectionMatrix();
      requestRender();
    },
    dispose() {
      disposed = true;
      controls.dispose();
      view.dispose();
      engine?.dispose();
      renderer.dispose();
      canvas.removeEventListener('webglcontextlost', onDisplayLost);
      canvas.removeEventListener('webglcontextrestored', onDisplayRestored);
      bakeCanvas.removeEventListener('webglcontextlost', onBakeLost);
      bakeCanvas.removeEventListener('webglcontextrestored', onBakeRestored);
      // Free the bake context now rather than when the garbage collector gets to it (browsers cap live contexts).
      bakeCanvas.getContext('webgl2')?.getExtension('WEBGL_lose_context')?.loseContext();
    },
  };
}

export type ViewerController = ReturnType<typeof createViewerController>;
