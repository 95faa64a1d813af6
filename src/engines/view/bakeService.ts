import type { BakeScene } from '../bake/bakeScene';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import type { EngineProgress, RelightEngine } from '../relight/RelightEngine';
import type { QualityLevel } from '../relight/qualityLevels';
import type { LightSources } from '../relight/daylightGroups';
import type { BakeCanvas } from './createBakeContext';
import type { GpuFence } from './createBakeSlicer';
import type { ServiceFade } from './service/serviceFade';

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
   * Which light the view shows (issue 30, docs/daylight.md "Daylight in the relight engine"):
   * 'electric' (the luminaires), 'daylight' (the sky and the sun through the windows), 'both'
   * (default) or 'daylight-factor' (the windows under a 10 klx CIE overcast sky: lux / 100 = DF %). Weights of the engine's bases: never a bake; kept across quality changes and a
   * restored context. Throws on another value.
   */
  setLightSources(sources: LightSources): void;
  readonly lightSources: LightSources;
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
