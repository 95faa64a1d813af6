import type { BakeScene } from '../bake/bakeScene';
import { encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { resolveBakeSettings, type BakeSettings } from '../bake/bakeSettings';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import type { EngineProgress, RelightEngine } from '../relight/RelightEngine';
import { QUALITY_LEVELS, type QualityLevel } from '../relight/qualityLevels';
import { createBakeContext, type BakeCanvas, type BakeContext } from './createBakeContext';
import { createBakeSlicer, glFence, glTimer, type BakeSlicer, type GpuFence } from './createBakeSlicer';
import { createObjectsMemo } from './createObjectsMemo';
import { lowMemoryDevice } from './lowMemoryDevice';

/** What a bake service tells its subscribers. */
export type BakeEvent =
  /** A slice ran (or a relight-only scene change arrived): new maps when `engine.version` moved. */
  | { type: 'slice'; engine: RelightEngine; progress: EngineProgress }
  /** The engine was replaced (quality change, context restore): maps on screen belong to the old one. */
  | { type: 'engine'; engine: RelightEngine | null }
  /** The bake context was lost or restored. */
  | { type: 'context'; state: 'lost' | 'restored' }
  | { type: 'error'; message: string }
  /** Paused or resumed (the tab was hidden or shown). */
  | { type: 'status' };

/** The service's state for hosts and tests (window.luxbox.view3d().bake). */
export interface BakeStatus {
  /** Work is pending and not paused. */
  running: boolean;
  /** Paused because the page is hidden. */
  paused: boolean;
  /** Every basis is final for the current scene (false before any scene). */
  done: boolean;
  /** Group bakes, relight-only scene changes and shared indirect solves since the service started (across engines). */
  groupBakes: number;
  relightsOnly: number;
  indirectSolves: number;
  /** Engines the service replaced because slices stopped moving the bake forward (STALL_SLICES); 0 on a healthy GPU. */
  restarts: number;
  quality: QualityLevel;
}

export interface BakeService {
  /** A new scene (any change of the configuration): replaces pending work; the engine keeps unchanged groups. */
  setScene(scene: BakeScene): void;
  readonly scene: BakeScene | null;
  /**
   * A transient change of the scene the engine lights (Live control's levels; only dimming and
   * colour, so a relight), or null for the scene itself.
   */
  setOverlay(overlay: ((scene: BakeScene) => BakeScene) | null): void;
  /**
   * A light-scene crossfade (docs/light-scenes.md): `from` turns the scene into the scene faded
   * from (same luminaires, other dimming and colour), `e` the eased fraction; null ends it. Each call
   * is a relight of the engine (no bake) and is announced as a slice at once, so the view draws it
   * in the same frame.
   */
  setFade(fade: ServiceFade | null): void;
  /**
   * Each luminaire's weight (dimming × colour, linear RGB) in the light shown now: the scene with the
   * overlay and, during a crossfade, (1 − e)·from + e·scene, as the engine mixes the bases. Null: no scene.
   */
  luminaireWeights(): Rgb[] | null;
  /** Another quality level: a fresh engine with QUALITY_LEVELS[level], which rebakes the scene. */
  setQuality(level: QualityLevel): void;
  readonly quality: QualityLevel;
  /** The engine, or null while its context is lost or when none could be made. */
  readonly engine: RelightEngine | null;
  /** The scene's objects as the engine lays out their atlas (null: none). */
  objects(): PreparedObjects | null;
  status(): BakeStatus;
  /** The last error (null: none). */
  readonly error: string | null;
  subscribe(listener: (event: BakeEvent) => void): () => void;
  dispose(): void;
}

/** A crossfade as the service takes it: the scene faded from as a function of the (lit) scene. */
export interface ServiceFade {
  from: (scene: BakeScene) => BakeScene;
  e: number;
}

/** The page visibility the service follows (the document, or a test's stand-in). */
export type VisibilitySource = Pick<Document, 'hidden' | 'addEventListener' | 'removeEventListener'>;

export interface BakeServiceOptions {
  quality?: QualityLevel;
  /** Default: the page's document (no pausing without one). */
  visibility?: VisibilitySource | null;
  /** A new canvas for the bake context (default: a detached canvas). */
  canvas?: () => BakeCanvas;
  /** Fences after slices (default: glFence on the engine's context). */
  fence?: ((gl: WebGL2RenderingContext) => GpuFence | null) | null;
  /** setTimeout and performance.now, or a test's stand-ins. */
  defer?: (callback: () => void, ms: number) => unknown;
  now?: () => number;
  /**
   * Where user input is watched (default: the window; null: nowhere). Bake work waits until the
   * input has been quiet for inputQuietMs: a slice cannot be interrupted once issued, and on a
   * slow GPU one step (a group's direct light with objects) can take seconds.
   */
  input?: Pick<EventTarget, 'addEventListener' | 'removeEventListener'> | null;
  /** Default INPUT_QUIET_MS. */
  inputQuietMs?: number;
  /**
   * Free the baker's GPU targets once the bake is done (they are only a cache for the next bake).
   * Default: navigator.deviceMemory ≤ 2 (GB).
   */
  lowMemory?: boolean;
}

/** Quiet time after the last pointer, key or wheel input before bake work starts again, ms. */
export const INPUT_QUIET_MS = 800;

/**
 * Slices in a row that issued work but left the engine's progress (groups based, fraction) where it
 * was, before the service replaces the engine and bakes the scene afresh. A healthy engine moves
 * its progress on every step except the first half of a direct basis (issue, then read back), so
 * two in a row never happen; this bound only trips on a broken engine or context (issue 32).
 */
export const STALL_SLICES = 20;

/** Input that means the user is interacting (a hovering pointer does not count). */
const INPUT_EVENTS = ['pointerdown', 'pointermove', 'keydown', 'wheel', 'touchstart'] as const;

/**
 * The 3D view's bake, living as long as the configurator rather than the view (docs/viewer.md,
 * "Always ready: the bake service"): the bake context and its relight engine, the background
 * slicer and the objects' atlas layout. Hosts feed it every configuration change; it bakes in
 * fenced background slices whether or not the view is open, pauses while the page is hidden,
 * and a new scene replaces the pending work. No three.js here: it is its own small chunk.
 */
export function createBakeService(options: BakeServiceOptions = {}): BakeService {
  let quality: QualityLevel = options.quality ?? 'balanced';
  const visibility = options.visibility !== undefined ? options.visibility : typeof document === 'undefined' ? null : document;
  const lowMemory = options.lowMemory ?? lowMemoryDevice();
  const input = options.input !== undefined ? options.input : typeof window === 'undefined' ? null : window;
  const quietMs = options.inputQuietMs ?? INPUT_QUIET_MS;
  const clock = options.now ?? (() => performance.now());
  let lastInput = -Infinity;
  const onInput = (e: Event) => {
    if (e.type === 'pointermove' && (e as PointerEvent).buttons === 0) return;
    lastInput = clock();
  };
  const listen = { capture: true, passive: true };
  const listeners = new Set<(event: BakeEvent) => void>();
  const emit = (event: BakeEvent) => {
    for (const l of [...listeners]) l(event);
  };
  let scene: BakeScene | null = null;
  let overlay: ((s: BakeScene) => BakeScene) | null = null;
  let fade: ServiceFade | null = null;
  let error: string | null = null;
  let disposed = false;
  const prepareFor = createObjectsMemo();
  let prepared: PreparedObjects | null = null;
  /** Targets freed for the engine version that finished (low memory), so the free runs once per bake. */
  let trimmedAt = -1;

  // A room of any shape is lit as the baker bakes it, inside its enclosure (encloseShapedRoom: remembered per shape and objects, so every change of dimming keeps one atlas).
  const lit = (s: BakeScene) => encloseShapedRoom(overlay ? overlay(s) : s);
  /** The engine's scene and, during a fade, its fade; a fade whose scenes no longer match (a module added meanwhile) ends. */
  const light = (engine: RelightEngine | null, s: BakeScene) => {
    if (!engine) return;
    const shown = lit(s);
    engine.setScene(shown);
    if (!fade) return;
    try {
      engine.setFade({ from: fade.from(shown), e: fade.e });
    } catch {
      fade = null;
      engine.setFade(null);
    }
  };
  // Each quality level's settings resolved once and passed on: the engine and its baker take them as they are.
  const resolvedLevels = new Map<QualityLevel, BakeSettings>();
  const levelSettings = (level: QualityLevel): BakeSettings => {
    const known = resolvedLevels.get(level);
    if (known) return known;
    const resolved = resolveBakeSettings(QUALITY_LEVELS[level]);
    resolvedLevels.set(level, resolved);
    return resolved;
  };
  const settings = () => context.engine?.settings ?? levelSettings(quality);
  const reportError = (message: string) => {
    error = message;
    emit({ type: 'error', message });
  };

  const context: BakeContext = createBakeContext(
    {
      onLost: () => emit({ type: 'context', state: 'lost' }),
      onRestored(engine) {
        if (scene) light(engine, scene);
        emit({ type: 'engine', engine });
        emit({ type: 'context', state: 'restored' });
        slicer.queue();
      },
      onError: reportError,
    },
    { settings: levelSettings(quality), canvas: options.canvas },
  );

  /**
   * The service watches its own progress (issue 32): the slicer guarantees a step per slice and a
   * next slice until done; this guards against steps that do not move the bake. After STALL_SLICES
   * working slices without progress the engine is replaced (as a quality change would) and the
   * scene baked afresh.
   */
  let restarts = 0;
  let lastProgress = '';
  let stalledSlices = 0;
  const restart = () => {
    restarts++;
    stalledSlices = 0;
    lastProgress = '';
    const engine = context.setSettings(levelSettings(quality));
    if (scene) light(engine, scene);
    emit({ type: 'engine', engine });
    slicer.queue();
  };
  const watchProgress = (progress: EngineProgress, samples: number): boolean => {
    if (samples === 0 || progress.done) return false;
    const now = `${progress.groupsDone}/${progress.groups}:${progress.fraction}`;
    stalledSlices = now === lastProgress ? stalledSlices + 1 : 0;
    lastProgress = now;
    return stalledSlices >= STALL_SLICES;
  };

  const makeFence = options.fence === undefined ? glFence : options.fence;
  const slicer: BakeSlicer = createBakeSlicer({
    engine: () => context.engine,
    onSlice(engine, progress, samples) {
      if (progress.done && lowMemory && trimmedAt !== engine.version) {
        trimmedAt = engine.version;
        engine.releaseTargets();
      }
      emit({ type: 'slice', engine, progress });
      if (watchProgress(progress, samples)) restart();
    },
    onError: reportError,
    defer: options.defer,
    now: options.now,
    fence: makeFence ? () => (context.gl ? makeFence(context.gl) : null) : undefined,
    // Sized by GPU time where EXT_disjoint_timer_query_webgl2 exists (docs/viewer.md); with fences only.
    timer: makeFence ? () => (context.gl ? glTimer(context.gl) : null) : undefined,
    holdMs: () => Math.max(0, lastInput + quietMs - clock()),
  });
  if (input) for (const type of INPUT_EVENTS) input.addEventListener(type, onInput, listen);

  const onVisibility = () => {
    if (!visibility) return;
    slicer.setPaused(visibility.hidden);
    emit({ type: 'status' });
  };
  if (visibility) {
    visibility.addEventListener('visibilitychange', onVisibility);
    slicer.setPaused(visibility.hidden);
  }

  return {
    setScene(next) {
      if (disposed) return;
      scene = next;
      prepared = prepareFor(encloseShapedRoom(next).objects, settings());
      light(context.engine, next);
      slicer.queue();
    },
    get scene() {
      return scene;
    },
    luminaireWeights() {
      if (!scene) return null;
      const shown = lit(scene);
      const weight = (l: BakeScene['luminaires'][number]): Rgb => {
        const d = Math.max(0, l.dimming ?? 1);
        const c = l.color ?? [1, 1, 1];
        return [d * c[0], d * c[1], d * c[2]];
      };
      const now = shown.luminaires.map(weight);
      if (!fade) return now;
      try {
        const from = fade.from(shown).luminaires.map(weight);
        if (from.length !== now.length) return now;
        const e = fade.e;
        return now.map((w, i) => w.map((c, k) => (1 - e) * from[i][k] + e * c) as Rgb);
      } catch {
        return now;
      }
    },
    setOverlay(next) {
      overlay = next;
      if (!scene || disposed) return;
      light(context.engine, scene);
      slicer.queue();
    },
    setFade(next) {
      if (disposed || (next === null && fade === null)) return;
      fade = next;
      const engine = context.engine;
      if (!engine || !scene) return;
      if (!fade) engine.setFade(null);
      else {
        try {
          engine.setFade({ from: fade.from(lit(scene)), e: fade.e });
        } catch {
          // The scene faded from does not match the one the engine holds (its luminaires changed): show the scene.
          fade = null;
          engine.setFade(null);
        }
      }
      // Drawn now (a relight), not after the input-quiet hold of bake work; the end state's solve, if new, is queued.
      emit({ type: 'slice', engine, progress: engine.progress });
      slicer.queue();
    },
    setQuality(level) {
      if (level === quality || disposed) return;
      quality = level;
      const engine = context.setSettings(levelSettings(level));
      if (scene) prepared = prepareFor(encloseShapedRoom(scene).objects, settings());
      if (scene) light(engine, scene);
      emit({ type: 'engine', engine });
      slicer.queue();
    },
    get quality() {
      return quality;
    },
    get engine() {
      return context.engine;
    },
    objects: () => prepared,
    status() {
      const engine = context.engine;
      const done = scene !== null && engine !== null && engine.progress.done;
      return { running: !done && !slicer.paused && scene !== null && engine !== null, paused: slicer.paused, done, ...context.counters(), restarts, quality };
    },
    get error() {
      return error;
    },
    subscribe(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    dispose() {
      if (disposed) return;
      disposed = true;
      visibility?.removeEventListener('visibilitychange', onVisibility);
      if (input) for (const type of INPUT_EVENTS) input.removeEventListener(type, onInput, listen);
      slicer.stop();
      listeners.clear();
      context.dispose();
    },
  };
}
