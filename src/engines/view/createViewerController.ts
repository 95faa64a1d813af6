import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import type { BakeService } from './createBakeService';
import { createCameraRig } from './createCameraRig';
import { createCompileGate } from './createCompileGate';
import { createFrameScheduler } from './createFrameScheduler';
import { createMapDisplay } from './createMapDisplay';
import { createRoomView } from './roomView';
import { watchContextLoss } from './watchContextLoss';
import { watchTaps } from './watchTaps';
import { createSpotlight } from './createSpotlight';
import { initialViewerState, type Viewer, type ViewerEvents } from './controller/viewer';
import { viewerSpotlightDeps } from './controller/viewerOverlay';
import { drawViewerFrame, followBakeService, restoreViewer, tapViewer } from './controller/viewerLifecycle';
import { viewerSceneApi } from './controller/viewerSceneApi';
import { viewerDisplayApi } from './controller/viewerDisplayApi';
import { viewerLightApi } from './controller/viewerLightApi';
import { viewerCompareApi } from './controller/viewerCompareApi';
import { createViewerGpu, disposeViewerGpu, gpuViewStatus } from './controller/gpuRelightFrame';

export type { CompareRequest, ViewerEvents } from './controller/viewer';

/**
 * The imperative core of the 3D view (three.js, no React): renders on demand
 * only (createFrameScheduler), shows the maps of the bake service's engine
 * (createBakeService: it outlives the view, bakes in background slices and
 * relights instantly when only dimming or colour changed), survives WebGL
 * context loss. On creation it shows the engine's current maps at once: a view
 * opened again with nothing changed bakes nothing. Disposing it frees the
 * display (renderer, room view), never the service.
 *
 * The parts share one `Viewer` (controller/viewer.ts): its state and the parts below. Each
 * part's callbacks read it when called, after it is wired.
 */
export function createViewerController(canvas: HTMLCanvasElement, service: BakeService, events: ViewerEvents) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, powerPreference: 'high-performance' });
  renderer.setPixelRatio(Math.min(2, window.devicePixelRatio || 1));
  const state = initialViewerState(createRoomView(renderer));
  const controls = new OrbitControls(state.view.camera, canvas);
  controls.enableDamping = false; // damping needs a continuous loop; we render on demand
  controls.screenSpacePanning = true;

  const display = watchContextLoss(canvas, { lost: () => events.onContext('lost'), restored: () => restoreViewer(v) });
  // Three's programs compile before a frame draws them, without blocking (createCompileGate.ts): the frame waits, the page does not.
  const compiles = createCompileGate({
    key: () => (v.compare && v.compareView ? `${v.view.materialsKey()}|${v.compareView.materialsKey()}` : v.view.materialsKey()),
    compile: () => Promise.all([v.view.compileAsync(renderer), ...(v.compare && v.compareView ? [v.compareView.compileAsync(renderer)] : [])]),
    onReady: () => frames.request(),
  });
  const frames = createFrameScheduler({
    draw: () => {
      drawViewerFrame(v);
      compiles.drawn();
    },
    canDraw: () => v.active && !display.lost && compiles.ready(),
    onFrame: events.onFrame,
  });
  controls.addEventListener('change', frames.request);
  const camera = createCameraRig(controls, state.view);
  const stopTaps = watchTaps(canvas, (x, y) => tapViewer(v, x, y));
  const spotlight = createSpotlight(viewerSpotlightDeps(canvas, controls, renderer.extensions.has('OES_texture_float_linear'), () => v));
  const maps = createMapDisplay(() => v.view, events.onMaps);
  const gpu = createViewerGpu({ renderer });
  const v: Viewer = Object.assign(state, { renderer, service, events, controls, display, frames, camera, spotlight, maps, gpu });

  const unsubscribe = followBakeService(v);
  if (service.error) queueMicrotask(() => events.onError(service.error!));

  return {
    ...viewerSceneApi(v),
    ...viewerDisplayApi(v),
    ...viewerLightApi(v),
    ...viewerCompareApi(v),
    /** Read-backs, uploads and texture memory of the view's relight, and its asynchronous compiles (`view3d().gpu`). */
    gpuStatus: () => gpuViewStatus(v.gpu, compiles.counters),
    /** The work plane whose statistics follow each GPU relight (onWorkPlaneStats), or null: off. */
    setWorkPlane(height: number | null) {
      v.gpu.workPlaneHeight = height;
    },
    /** Frees the display only: the service keeps its engine, maps and pending work. */
    dispose() {
      v.compareView?.dispose();
      unsubscribe();
      if (v.live) service.setOverlay(null);
      frames.stop();
      compiles.dispose();
      stopTaps();
      spotlight.dispose();
      controls.dispose();
      disposeViewerGpu(gpu);
      v.view.dispose();
      renderer.dispose();
      display.dispose();
    },
  };
}

export type ViewerController = ReturnType<typeof createViewerController>;
