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

export function createScenePlayer(store: ConfiguratorStore, options: ScenePlayerOptions = {}): ScenePlayer {
  const frame = options.frame ?? pageFrame;
  const now = options.now ?? (() => performance.now());
  const listeners = new Set<() => void>();
  let state: ScenePlayerState = { current: null, fading: null };
  let run: { start: number; yFrom: number; yTo: number; cancelFrame: () => void; resolve: (r: RecallResult) => void; lights: ReadonlyMap<string, ModuleLight> } | null = null;
  const set = (next: ScenePlayerState) => {
    state = next;
    for (const l of [...listeners]) l();
  };
  const scenes = () => store.getState().config.lightScenes ?? [];
  const feed = () => options.feed?.() ?? null;

  const showFade = (f: SceneFadeState) => {
    const bake = feed();
    if (!bake || !run) return;
    const lights = run.lights;
    bake.service.setFade({ from: (scene) => fromScene(scene, bake.latest()?.ids ?? [], lights), e: f.e });
  };

  const end = () => {
    if (!run) return;
    const r = run;
    run = null;
    r.cancelFrame();
    feed()?.service.setFade(null);
    set({ ...state, fading: null });
    r.resolve({ ok: true });
  };

  /** The running fade's time fraction and eased fraction at this instant. */
  const position = (f: SceneFadeState, r: NonNullable<typeof run>) => {
    const t = f.seconds > 0 ? Math.min(1, (now() - r.start) / (f.seconds * 1000)) : 1;
    return { t, e: fadeFraction(t, r.yFrom, r.yTo) };
  };

  /** The look shown now, as levels (the plan) and lights (the 3D view): the running fade's mix at this instant, else the configuration's. */
  const shownLook = (config: Configuration, catalog: Catalog) => {
    const f = state.fading;
    if (!run || !f) return { levels: outputLevels(config), lights: lightsOf(config, catalog), fading: false };
    const { e } = position(f, run);
    return { levels: mixLevels(f.fromLevels, outputLevels(f.to), e), lights: mixLights(run.lights, lightsOf(f.to, catalog), e), fading: true };
  };

  const tick = () => {
    if (!run || !state.fading) return;
    const f = state.fading;
    const { t, e } = position(f, run);
    if (t >= 1) return end();
    const next = { ...f, t, e };
    set({ ...state, fading: next });
    showFade(next);
    run.cancelFrame = frame(tick);
  };

  // Any other change of the configuration (an edit, undo) during a fade ends it: the plan and the view show the configuration.
  const unsubscribe = store.subscribe((s, prev) => {
    if (s.config !== prev.config && state.fading && s.config !== state.fading.to) end();
  });

  const player: ScenePlayer = {
    getState: () => state,
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    recall(sceneId, opts = {}) {
      // The fade weights each module's light by its colour: a filter's needs the spectra (docs/colour-filters.md, "Two files").
      if (needsColourFilterSpectra(configurationFilterIds(store.getState().config))) {
        return loadColourFilterSpectra().then(
          () => player.recall(sceneId, opts),
          (e: Error) => ({ ok: false, reason: `the colour filters' spectra could not be loaded (${e.message})` }),
        );
      }
      const { catalog, config: from } = store.getState();
      // Taken before the running fade ends: a recall during a fade starts from the mix on screen.
      const shown = shownLook(from, catalog);
      end();
      const scene = scenes().find((s) => s.id === sceneId);
      const result = store.getState().dispatch('recallScene', { sceneId });
      if (!result.ok) return Promise.resolve({ ok: false, reason: result.reason });
      const to = store.getState().config;
      const seconds = opts.fade ?? scene?.fade ?? 0;
      if (!(seconds > 0) || (to === from && !shown.fading)) {
        set({ current: sceneId, fading: null });
        return Promise.resolve({ ok: true });
      }
      return new Promise<RecallResult>((resolve) => {
        run = { start: now(), yFrom: levelsOutput(shown.levels, to, catalog), yTo: levelsOutput(outputLevels(to), to, catalog), cancelFrame: () => undefined, resolve, lights: shown.lights };
        const fading: SceneFadeState = { sceneId, fromLevels: shown.levels, to, t: 0, e: 0, seconds };
        set({ current: sceneId, fading });
        showFade(fading);
        run.cancelFrame = frame(tick);
      });
    },
    next() {
      const list = scenes();
      const i = list.findIndex((s) => s.id === state.current);
      return list[i + 1] ?? null;
    },
    previous() {
      const list = scenes();
      const i = list.findIndex((s) => s.id === state.current);
      return i > 0 ? list[i - 1] : null;
    },
    go() {
      const s = player.next();
      const code = player.stop('go');
      return s ? player.recall(s.id) : Promise.resolve({ ok: false, reason: code === 'noScenes' ? 'no light scenes' : 'no next scene', code: code ?? 'lastScene' });
    },
    back() {
      const s = player.previous();
      const code = player.stop('back');
      return s ? player.recall(s.id) : Promise.resolve({ ok: false, reason: code === 'noScenes' ? 'no light scenes' : 'no previous scene', code: code ?? 'firstScene' });
    },
    stop(direction) {
      const list = scenes();
      if (list.length === 0) return 'noScenes';
      if (direction === 'go') return player.next() ? null : 'lastScene';
      if (player.previous()) return null;
      return list.some((s) => s.id === state.current) ? 'firstScene' : 'nothingRecalled';
    },
    levels() {
      const f = state.fading;
      return f ? mixLevels(f.fromLevels, outputLevels(f.to), f.e) : null;
    },
    finish: end,
    dispose() {
      end();
      unsubscribe();
      listeners.clear();
    },
  };
  return player;
}

/**
 * The store's scene player, created on first use with the options first given to it or to its
 * handle (scenePlayerHandle.ts): the panel, the keys, the plan and the embedding API share it.
 */
export function scenePlayerFor(store: ConfiguratorStore, options?: ScenePlayerOptions): ScenePlayer {
  return playerOf(store, options, (o) => createScenePlayer(store, o));
}
