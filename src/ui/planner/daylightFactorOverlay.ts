import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { LightSources } from '../../engines/relight/daylightGroups';
import { bakeHostOf } from '../viewer/bakeHost';
import type { BakeFeed } from '../viewer/startBakeFeed';
import { webglSupportProblem } from '../viewer/webglSupport';
import { computeDaylightFactorGrid, type DaylightFactorGrid, type SliceScheduler } from './daylightFactorGrid';

/**
 * What the plan's daylight-factor overlay shows: `off`; `computing` (the bake service is baking
 * the overcast basis or the grid is being lit; the last grid, if any, stays drawn faded);
 * `ready`; `no-sky` (the configuration's scene has no sky: the sun is below the horizon at the
 * chosen time, docs/daylight.md "The shopper's daylight"); `unavailable` (no WebGL, or the bake failed).
 */
export type OverlayPhase = 'off' | 'computing' | 'ready' | 'no-sky' | 'unavailable';

export interface OverlaySnapshot {
  on: boolean;
  phase: OverlayPhase;
  grid: DaylightFactorGrid | null;
}

export interface DaylightFactorOverlay {
  snapshot(): OverlaySnapshot;
  subscribe(listener: () => void): () => void;
  /** The shopper's toggle; kept while the plan is left and shown again. */
  setOn(on: boolean): void;
  /** The plan shows the overlay's controls: while attached and on, the bake service shows the daylight factor. Returns the detach. */
  attach(): () => void;
}

/** Quiet time after the last change before the grid is lit (ms): a window dragged along its wall is lit once, where it is let go. */
export const GRID_DEBOUNCE_MS = 250;

const overlays = new WeakMap<ConfiguratorStore, DaylightFactorOverlay>();

/** The store's overlay (one per configurator, so the toggle survives the 3D view and back). */
export function daylightFactorOverlayOf(store: ConfiguratorStore): DaylightFactorOverlay {
  let overlay = overlays.get(store);
  if (!overlay) {
    // No WebGL 2 or float targets: no bake service to ask (the card says why).
    overlay = createDaylightFactorOverlay(store, () => (webglSupportProblem() ? null : (bakeHostOf(store)?.get() ?? null)));
    overlays.set(store, overlay);
  }
  return overlay;
}

/** Test seams: the timer and the slice scheduler. */
export interface OverlayOptions {
  schedule?: SliceScheduler;
  delay?: (callback: () => void, ms: number) => () => void;
}

const timeout = (callback: () => void, ms: number) => {
  const id = setTimeout(callback, ms);
  return () => clearTimeout(id);
};

/**
 * `feedOf` gives the store's bake feed (null: none can be made: no bake host, no WebGL 2).
 * The overlay's state: while on and attached it asks the store's bake service (the one the 3D view
 * draws from) for the 'daylight-factor' light, and lights the work-plane grid from its maps once
 * the engine has settled (debounced); off or detached, it gives the service back the light it had.
 */
export function createDaylightFactorOverlay(store: ConfiguratorStore, feedOf: () => Promise<BakeFeed> | null, options: OverlayOptions = {}): DaylightFactorOverlay {
  const delay = options.delay ?? timeout;
  const listeners = new Set<() => void>();
  let state: OverlaySnapshot = { on: false, phase: 'off', grid: null };
  let attached = 0;
  let session: (() => void) | null = null;
  const set = (patch: Partial<OverlaySnapshot>) => {
    const next = { ...state, ...patch };
    if (next.on === state.on && next.phase === state.phase && next.grid === state.grid) return;
    state = next;
    listeners.forEach((l) => l());
  };
  const update = () => {
    const active = state.on && attached > 0;
    if (active && !session) session = startSession(store, feedOf, set, () => state.grid, delay, options.schedule);
    if (!active && session) {
      session();
      session = null;
    }
    if (!state.on) set({ phase: 'off' });
  };
  return {
    snapshot: () => state,
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    setOn(on) {
      set({ on, ...(on ? { phase: 'computing' as const } : {}) });
      update();
    },
    attach() {
      attached++;
      update();
      let detached = false;
      return () => {
        if (detached) return;
        detached = true;
        attached--;
        update();
      };
    },
  };
}

/** One stretch of the overlay being on: the service's light, its events, the grid's computation; returns the end. */
function startSession(
  store: ConfiguratorStore,
  feedOf: () => Promise<BakeFeed> | null,
  set: (patch: Partial<OverlaySnapshot>) => void,
  grid: () => DaylightFactorGrid | null,
  delay: NonNullable<OverlayOptions['delay']>,
  schedule?: SliceScheduler,
): () => void {
  let ended = false;
  let feed: BakeFeed | null = null;
  let before: LightSources | null = null;
  let cancelWait: () => void = () => undefined;
  let cancelGrid: (() => void) | null = null;
  let computing: number | null = null;
  const unsubscribe: (() => void)[] = [];

  const light = () => {
    if (!feed || ended) return;
    const { service } = feed;
    const engine = service.engine;
    if (service.error || feed.error()) return set({ phase: 'unavailable' });
    if (!service.scene || feed.pending() || !engine) return set({ phase: 'computing' });
    if (!service.scene.daylight) return set({ phase: 'no-sky' });
    if (!engine.progress.done) return set({ phase: 'computing' });
    const version = engine.version;
    if (grid()?.version === version) return set({ phase: 'ready' });
    if (computing === version) return;
    cancelGrid?.();
    computing = version;
    set({ phase: 'computing' });
    const scene = service.scene;
    cancelGrid = computeDaylightFactorGrid(
      scene,
      engine.maps(),
      service.objects(),
      version,
      (g) => {
        cancelGrid = null;
        computing = null;
        // The engine moved on while the grid was lit: its maps were another light; light it again.
        if (service.engine !== engine || engine.version !== version || service.scene !== scene) return changed();
        set(g ? { grid: g, phase: 'ready' } : { grid: null, phase: 'no-sky' });
      },
      schedule,
    );
  };
  // Every change (a slice, a new scene, the configuration edited) shows "computing" at once when the light is not settled, and lights the grid once quiet.
  const changed = () => {
    if (ended) return;
    const engine = feed?.service.engine;
    if (!engine?.progress.done || feed?.pending()) set({ phase: 'computing' });
    cancelWait();
    cancelWait = delay(light, GRID_DEBOUNCE_MS);
  };

  const loading = feedOf();
  if (!loading) set({ phase: 'unavailable' });
  loading?.then(
    (f) => {
      if (ended) return;
      feed = f;
      before = f.service.lightSources;
      f.service.setLightSources('daylight-factor');
      unsubscribe.push(f.service.subscribe(changed), f.subscribe(changed), store.subscribe(changed));
      changed();
    },
    () => !ended && set({ phase: 'unavailable' }),
  );
  return () => {
    ended = true;
    cancelWait();
    cancelGrid?.();
    unsubscribe.forEach((u) => u());
    // The light the service showed before (the 3D view hands its own again when it is shown).
    if (feed && before && feed.service.lightSources === 'daylight-factor') feed.service.setLightSources(before);
  };
}
