/**
 * Light-scene playback (docs/light-scenes.md, "Playback"): recall a scene with its crossfade, GO
 * and BACK through the list like a lighting console. Recalling is one undoable action
 * (recallScene: the configuration jumps to the end state at once); the fade is playback, not
 * configuration: for its duration the plan shows each module's level at the eased fraction
 * (fadeLevels) and the 3D view is relit every frame from the two scenes' weights (the bake
 * service's setFade: no bake). One player per configurator store, shared by the scene panel, the
 * keyboard and the embedding API.
 */
import { loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { needsColourFilterSpectra } from '../../core/colour/moduleColour';
import { configurationFilterIds } from '../../core/model/modules/moduleFilter';
import type { Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { Configuration, LightScene } from '../../core/model/configuration/configuration';
import { fadeFraction, levelsOutput, mixLevels, mixLights, outputLevels, type ModuleLight } from '../../core/model/cues/sceneFade';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';
import type { BakeFeed } from '../viewer/startBakeFeed';
import { fromScene, lightsOf } from '../../engines/view/sceneLights';
import { playerOf } from './scenePlayerHandle';

export interface SceneFadeState {
  readonly sceneId: string;
  /**
   * Each module's output level when the fade began (module id → level, off = 0): the configuration
   * before the recall, or, when the recall interrupted another fade, that fade's mix at that instant.
   */
  readonly fromLevels: ReadonlyMap<string, number>;
  readonly to: Configuration;
  /** Time fraction 0..1 and the eased fade fraction e(t) (sceneFade.ts). */
  readonly t: number;
  readonly e: number;
  /** Fade time, seconds. */
  readonly seconds: number;
}

export interface ScenePlayerState {
  /** The scene recalled last (GO and BACK step from it); null before any. */
  readonly current: string | null;
  readonly fading: SceneFadeState | null;
}

/** A refused recall: the reason in English, and for GO / BACK at the ends of the list a code the panel words (scenes.lastScene, …). */
export type RecallResult = { readonly ok: true } | { readonly ok: false; readonly reason: string; readonly code?: TransportStop };

/**
 * Why GO or BACK has nothing to recall, like a console at the end of its cue list (GO at the last
 * cue does not wrap round to the first): no scenes, GO at the last scene, BACK at the first, BACK
 * before any scene was recalled.
 */
export type TransportStop = 'noScenes' | 'lastScene' | 'firstScene' | 'nothingRecalled';

export interface ScenePlayer {
  getState(): ScenePlayerState;
  subscribe(listener: () => void): () => void;
  /**
   * Recalls a scene with a fade of `fade` seconds (default: the scene's own); resolves when the fade
   * ends (or is cut short). During another fade the new one starts from the look shown at that
   * instant (the running fade's mix), as a console's cue fades from the stage's current state.
   */
  recall(sceneId: string, options?: { fade?: number }): Promise<RecallResult>;
  /** The next scene in list order after the current one (the first when none was recalled), or null at the end. */
  next(): LightScene | null;
  /** The previous scene in list order, or null at the start. */
  previous(): LightScene | null;
  go(): Promise<RecallResult>;
  back(): Promise<RecallResult>;
  /** Why GO (`'go'`) or BACK (`'back'`) would do nothing now, or null when it recalls a scene. */
  stop(direction: 'go' | 'back'): TransportStop | null;
  /** Each module's shown output level during a fade (off = 0), null when no fade runs. */
  levels(): ReadonlyMap<string, number> | null;
  /** Ends a running fade at its end state now. */
  finish(): void;
  dispose(): void;
}

export interface ScenePlayerOptions {
  /** The running bake feed, if any (the 3D view's light); null: the fade is shown in the plan only. */
  feed?: () => BakeFeed | null;
  /** requestAnimationFrame and performance.now, or a test's stand-ins. */
  frame?: (callback: () => void) => () => void;
  now?: () => number;
}

const pageFrame = (callback: () => void): (() => void) => {
  if (typeof requestAnimationFrame === 'function') {
    const id = requestAnimationFrame(() => callback());
    return () => cancelAnimationFrame(id);
  }
  const id = setTimeout(callback, 16);
  return () => clearTimeout(id);
};

type FadeRun = { start: number; yFrom: number; yTo: number; cancelFrame: () => void; resolve: (r: RecallResult) => void; lights: ReadonlyMap<string, ModuleLight> };

/** What the player's parts share: the store, the clock, the listeners, the state and the running fade. */
interface PlayerCore {
  readonly store: ConfiguratorStore;
  readonly frame: (callback: () => void) => () => void;
  readonly now: () => number;
  readonly feed: () => BakeFeed | null;
  readonly listeners: Set<() => void>;
  state: ScenePlayerState;
  run: FadeRun | null;
}

const setState = (core: PlayerCore, next: ScenePlayerState) => {
  core.state = next;
  for (const l of [...core.listeners]) l();
};
const scenesOf = (core: PlayerCore) => core.store.getState().config.lightScenes ?? [];

/** The fade on the 3D view: the bake service relights from the two scenes' weights (no bake). */
function showFade(core: PlayerCore, f: SceneFadeState) {
  const bake = core.feed();
  if (!bake || !core.run) return;
  const lights = core.run.lights;
  bake.service.setFade({ from: (scene) => fromScene(scene, bake.latest()?.ids ?? [], lights), e: f.e });
}

/** Ends the running fade at its end state (the configuration already is that state). */
function endFade(core: PlayerCore) {
  if (!core.run) return;
  const r = core.run;
  core.run = null;
  r.cancelFrame();
  core.feed()?.service.setFade(null);
  setState(core, { ...core.state, fading: null });
  r.resolve({ ok: true });
}

/** The running fade's time fraction and eased fraction at this instant. */
function position(core: PlayerCore, f: SceneFadeState, r: FadeRun) {
  const t = f.seconds > 0 ? Math.min(1, (core.now() - r.start) / (f.seconds * 1000)) : 1;
  return { t, e: fadeFraction(t, r.yFrom, r.yTo) };
}

/** The look shown now, as levels (the plan) and lights (the 3D view): the running fade's mix at this instant, else the configuration's. */
function shownLook(core: PlayerCore, config: Configuration, catalog: Catalog) {
  const f = core.state.fading;
  if (!core.run || !f) return { levels: outputLevels(config), lights: lightsOf(config, catalog), fading: false };
  const { e } = position(core, f, core.run);
  return { levels: mixLevels(f.fromLevels, outputLevels(f.to), e), lights: mixLights(core.run.lights, lightsOf(f.to, catalog), e), fading: true };
}

function tick(core: PlayerCore) {
  const { run, state } = core;
  if (!run || !state.fading) return;
  const { t, e } = position(core, state.fading, run);
  if (t >= 1) return endFade(core);
  const next = { ...state.fading, t, e };
  setState(core, { ...state, fading: next });
  showFade(core, next);
  run.cancelFrame = core.frame(() => tick(core));
}

/** Recalls a scene (one undoable action) and runs its fade from the look on screen; see ScenePlayer.recall. */
function recall(core: PlayerCore, sceneId: string, opts: { fade?: number }): Promise<RecallResult> {
  const { store } = core;
  // The fade weights each module's light by its colour: a filter's needs the spectra (docs/colour-filters.md, "Two files").
  if (needsColourFilterSpectra(configurationFilterIds(store.getState().config))) {
    return loadColourFilterSpectra().then(
      () => recall(core, sceneId, opts),
      (e: Error) => ({ ok: false, reason: `the colour filters' spectra could not be loaded (${e.message})` }),
    );
  }
  const { catalog, config: from } = store.getState();
  // Taken before the running fade ends: a recall during a fade starts from the mix on screen.
  const shown = shownLook(core, from, catalog);
  endFade(core);
  const scene = scenesOf(core).find((s) => s.id === sceneId);
  const result = store.getState().dispatch('recallScene', { sceneId });
  if (!result.ok) return Promise.resolve({ ok: false, reason: result.reason });
  const to = store.getState().config;
  const seconds = opts.fade ?? scene?.fade ?? 0;
  if (!(seconds > 0) || (to === from && !shown.fading)) {
    setState(core, { current: sceneId, fading: null });
    return Promise.resolve({ ok: true });
  }
  return new Promise<RecallResult>((resolve) => {
    const run: FadeRun = { start: core.now(), yFrom: levelsOutput(shown.levels, to, catalog), yTo: levelsOutput(outputLevels(to), to, catalog), cancelFrame: () => undefined, resolve, lights: shown.lights };
    core.run = run;
    const fading: SceneFadeState = { sceneId, fromLevels: shown.levels, to, t: 0, e: 0, seconds };
    setState(core, { current: sceneId, fading });
    showFade(core, fading);
    run.cancelFrame = core.frame(() => tick(core));
  });
}

/** GO / BACK through the list in order, stopping at its ends as a console does (no wrap round). */
function transport(core: PlayerCore, recallScene: (sceneId: string) => Promise<RecallResult>): Pick<ScenePlayer, 'next' | 'previous' | 'go' | 'back' | 'stop'> {
  const indexOfCurrent = (list: readonly LightScene[]) => list.findIndex((s) => s.id === core.state.current);
  const t: Pick<ScenePlayer, 'next' | 'previous' | 'go' | 'back' | 'stop'> = {
    next() {
      const list = scenesOf(core);
      return list[indexOfCurrent(list) + 1] ?? null;
    },
    previous() {
      const list = scenesOf(core);
      const i = indexOfCurrent(list);
      return i > 0 ? list[i - 1] : null;
    },
    go() {
      const s = t.next();
      const code = t.stop('go');
      return s ? recallScene(s.id) : Promise.resolve({ ok: false, reason: code === 'noScenes' ? 'no light scenes' : 'no next scene', code: code ?? 'lastScene' });
    },
    back() {
      const s = t.previous();
      const code = t.stop('back');
      return s ? recallScene(s.id) : Promise.resolve({ ok: false, reason: code === 'noScenes' ? 'no light scenes' : 'no previous scene', code: code ?? 'firstScene' });
    },
    stop(direction) {
      const list = scenesOf(core);
      if (list.length === 0) return 'noScenes';
      if (direction === 'go') return t.next() ? null : 'lastScene';
      if (t.previous()) return null;
      return list.some((s) => s.id === core.state.current) ? 'firstScene' : 'nothingRecalled';
    },
  };
  return t;
}

export function createScenePlayer(store: ConfiguratorStore, options: ScenePlayerOptions = {}): ScenePlayer {
  const core: PlayerCore = {
    store,
    frame: options.frame ?? pageFrame,
    now: options.now ?? (() => performance.now()),
    feed: () => options.feed?.() ?? null,
    listeners: new Set(),
    state: { current: null, fading: null },
    run: null,
  };
  // Any other change of the configuration (an edit, undo) during a fade ends it: the plan and the view show the configuration.
  const unsubscribe = store.subscribe((s, prev) => {
    const fading = core.state.fading;
    if (s.config !== prev.config && fading && s.config !== fading.to) endFade(core);
  });
  const recallScene = (sceneId: string, opts: { fade?: number } = {}) => recall(core, sceneId, opts);
  return {
    getState: () => core.state,
    subscribe(listener) {
      core.listeners.add(listener);
      return () => core.listeners.delete(listener);
    },
    recall: recallScene,
    ...transport(core, recallScene),
    levels() {
      const f = core.state.fading;
      return f ? mixLevels(f.fromLevels, outputLevels(f.to), f.e) : null;
    },
    finish: () => endFade(core),
    dispose() {
      endFade(core);
      unsubscribe();
      core.listeners.clear();
    },
  };
}

/**
 * The store's scene player, created on first use with the options first given to it or to its
 * handle (scenePlayerHandle.ts): the panel, the keys, the plan and the embedding API share it.
 */
export function scenePlayerFor(store: ConfiguratorStore, options?: ScenePlayerOptions): ScenePlayer {
  return playerOf(store, options, (o) => createScenePlayer(store, o));
}
