import { createBakeContext } from './createBakeContext';
import { createBakeSlicer, glFence, glTimer } from './createBakeSlicer';
import { createObjectsMemo } from './createObjectsMemo';
import { lowMemoryDevice } from './lowMemoryDevice';
import type { BakeEvent, BakeService, BakeServiceOptions } from './bakeService';
import { createStallWatch } from './service/createStallWatch';
import { levelSettingsMemo } from './service/levelSettingsMemo';
import { fadedWeights } from './service/serviceFade';
import { lightEngine, litScene, reportError, type ServiceCore, type ServiceState } from './service/serviceCore';
import { disposeService, restartService, serviceStatus, setServiceFade, setServiceLightSources, setServiceOverlay, setServiceQuality, setServiceScene } from './service/serviceMethods';
import { watchUserInput } from './service/watchUserInput';

export type { BakeEvent, BakeService, BakeServiceOptions, BakeStatus, VisibilitySource } from './bakeService';
export type { ServiceFade } from './service/serviceFade';

/** Quiet time after the last pointer, key or wheel input before bake work starts again, ms. */
export const INPUT_QUIET_MS = 800;

/**
 * Slices in a row that issued work but left the engine's progress (groups based, fraction) where it
 * was, before the service replaces the engine and bakes the scene afresh. A healthy engine moves
 * its progress on every step except the first half of a direct basis (issue, then read back), so
 * two in a row never happen; this bound only trips on a broken engine or context (issue 32).
 */
export const STALL_SLICES = 20;

/**
 * The 3D view's bake, living as long as the configurator rather than the view (docs/viewer.md,
 * "Always ready: the bake service"): the bake context and its relight engine, the background
 * slicer and the objects' atlas layout. Hosts feed it every configuration change; it bakes in
 * fenced background slices whether or not the view is open, pauses while the page is hidden,
 * and a new scene replaces the pending work. No three.js here: it is its own small chunk.
 * Its state and parts are one ServiceCore (service/serviceCore.ts); callbacks read it when called.
 */
export function createBakeService(options: BakeServiceOptions = {}): BakeService {
  const visibility = options.visibility !== undefined ? options.visibility : typeof document === 'undefined' ? null : document;
  const input = options.input !== undefined ? options.input : typeof window === 'undefined' ? null : window;
  const listeners = new Set<(event: BakeEvent) => void>();
  const emit = (event: BakeEvent) => {
    for (const l of [...listeners]) l(event);
  };
  const levelSettings = levelSettingsMemo();
  const quality = options.quality ?? 'balanced';
  // The state first: the context reports a failure to make its engine while it is created.
  const lowMemory = options.lowMemory ?? lowMemoryDevice();
  const state: ServiceState = {
    quality,
    scene: null,
    overlay: null,
    fade: null,
    lightSources: 'both',
    error: null,
    disposed: false,
    prepared: null,
    trimmedAt: -1,
    lowMemory,
    emit,
    listeners,
    levelSettings,
    prepareFor: createObjectsMemo(),
  };
  const context = createBakeContext(
    {
      onLost: () => emit({ type: 'context', state: 'lost' }),
      onRestored(engine) {
        if (c.scene) lightEngine(c, engine, c.scene);
        emit({ type: 'engine', engine });
        emit({ type: 'context', state: 'restored' });
        c.slicer.queue();
      },
      onError: (message) => reportError(state, message),
    },
    { settings: levelSettings(quality), canvas: options.canvas },
  );
  const userInput = watchUserInput(input, options.inputQuietMs ?? INPUT_QUIET_MS, options.now ?? (() => performance.now()));
  const makeFence = options.fence === undefined ? glFence : options.fence;
  const slicer = createBakeSlicer({
    engine: () => context.engine,
    onSlice(engine, progress, samples) {
      if (progress.done && c.lowMemory && c.trimmedAt !== engine.version) {
        c.trimmedAt = engine.version;
        engine.releaseTargets();
      }
      emit({ type: 'slice', engine, progress });
      if (c.stall.stalled(progress, samples)) restartService(c);
    },
    onError: (message) => reportError(c, message),
    defer: options.defer,
    now: options.now,
    fence: makeFence ? () => (context.gl ? makeFence(context.gl) : null) : undefined,
    // Sized by GPU time where EXT_disjoint_timer_query_webgl2 exists (docs/viewer.md); with fences only.
    timer: makeFence ? () => (context.gl ? glTimer(context.gl) : null) : undefined,
    holdMs: userInput.holdMs,
  });
  const c: ServiceCore = Object.assign(state, { context, slicer, stall: createStallWatch(STALL_SLICES), userInput });
  const stopVisibility = followVisibility(c, visibility);

  return serviceApi(c, listeners, stopVisibility);
}

/** The slicer pauses while the page is hidden (and says so); returns the stop. */
function followVisibility(c: ServiceCore, visibility: BakeServiceOptions['visibility']): () => void {
  if (!visibility) return () => undefined;
  const onVisibility = () => {
    c.slicer.setPaused(visibility.hidden);
    c.emit({ type: 'status' });
  };
  visibility.addEventListener('visibilitychange', onVisibility);
  c.slicer.setPaused(visibility.hidden);
  return () => visibility.removeEventListener('visibilitychange', onVisibility);
}

/** The service's methods over its core (what createBakeService returns). */
function serviceApi(c: ServiceCore, listeners: Set<(event: BakeEvent) => void>, stopVisibility: () => void): BakeService {
  const context = c.context;
  return {
    setScene: (next) => setServiceScene(c, next),
    get scene() {
      return c.scene;
    },
    luminaireWeights: () => (c.scene ? fadedWeights(litScene(c, c.scene), c.fade) : null),
    setOverlay: (next) => setServiceOverlay(c, next),
    setFade: (next) => setServiceFade(c, next),
    setLightSources: (sources) => setServiceLightSources(c, sources),
    get lightSources() {
      return c.lightSources;
    },
    setQuality: (level) => setServiceQuality(c, level),
    get quality() {
      return c.quality;
    },
    get engine() {
      return context.engine;
    },
    objects: () => c.prepared,
    status: () => serviceStatus(c),
    get error() {
      return c.error;
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    dispose: () => disposeService(c, stopVisibility),
  };
}
