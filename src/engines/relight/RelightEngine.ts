import type { BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { IndirectTerm, LitMaps, WeightedBasis } from './relightMaps';
import type { LightSources } from './daylightGroups';

export interface EngineProgress {
  /** Groups whose direct basis is baked. */
  groupsDone: number;
  groups: number;
  /** 0..1 over the pending work: the direct bases (a small first share), then the shared indirect solve. */
  fraction: number;
  /** Every group's direct basis is baked and the indirect light is solved at the current weights. */
  done: boolean;
  /** Every group has its direct basis: the image shows all the direct light. */
  lit: boolean;
  /** The indirect light shown is the finished solve at the current weights (not a preview, not a scaled earlier solve). */
  exact: boolean;
}

export interface EngineCounters {
  /** Direct bases of luminaire groups baked (a new or moved group counts once), since the engine was made. */
  groupBakes: number;
  /** Direct bases of daylight baked (the sky's and the sun's: a new time of day, date or sky counts each once), since the engine was made. */
  daylightBakes: number;
  /** Scene updates that needed no group bake (dimming, colour, on/off, removed groups only). */
  relightsOnly: number;
  /** Weighted sums computed. */
  relights: number;
  /** Shared indirect solves started (the first of a room and every re-solve after a change of weights or groups). */
  indirectSolves: number;
}

/**
 * What `maps()` sums, without summing it: the baked groups at the weights shown and the indirect
 * terms (indirectTerms.ts). The 3D view combines them on its GPU (createGpuRelight.ts).
 */
export interface RelightParts {
  parts: WeightedBasis[];
  terms: IndirectTerm[];
  layouts: Record<SurfaceName, SurfaceLayout>;
  atlas: ObjectAtlas | null;
  /** The engine version these parts are of. */
  version: number;
  /** A crossfade is shown (setFade): its fraction, else null. */
  fade: number | null;
}

/** The relight engine's kept daylight bases (RelightEngine.daylightCache). */
export interface DaylightCacheStatus {
  readonly size: number;
  readonly bytes: number;
  readonly budget: number;
  readonly evictions: number;
}

export interface SetSceneResult {
  /** Groups whose direct basis will be (re)baked (luminaire and daylight groups). */
  bake: number;
  /** Of those, the daylight groups (the sky, the sun); present only when the scene has daylight groups. */
  daylightBake?: number;
  /** Groups whose basis was kept. */
  reused: number;
}

/** A crossfade shown by the engine: weights (1 − e)·w_from + e·w_scene per group (docs/light-scenes.md). */
export interface EngineFade {
  /** The scene faded from: the same luminaires (geometry) as the current scene, other dimming and colour. */
  from: BakeScene;
  /** Fade fraction in [0, 1] (already eased): 0 shows `from`, 1 the scene. */
  e: number;
}

/**
 * Relighting by one shared indirect solve (docs/viewer.md, "Relighting without rebaking"). Each
 * luminaire group, and the daylight's sky and sun (daylightGroups.ts), gets a direct basis only (direct maps at unit weight, no bounces); the
 * indirect light of the whole scene is one solve from Σ_g w_g · direct_g (the gather reads only
 * the direct maps, and it is linear in them). A change of dimming or colour, or an added, moved
 * or removed group, shows the exact direct light at once and the last solve's indirect light
 * scaled per channel by Φ_now/Φ_solve (reflected direct flux, reflectedFlux.ts) until a
 * background re-solve at the new weights is done; a room or objects change rebakes every basis.
 * Work is progressive: `step` bakes one missing basis per call, then advances the solve by a
 * few samples (callers slice it over frames).
 */
export interface RelightEngine {
  setScene(scene: BakeScene): SetSceneResult;
  /**
   * Show a crossfade from `fade.from` to the current scene at fraction `fade.e`, or null for the scene
   * itself: a relight, never a bake. The direct light is Σ_g ((1 − e)·w_from + e·w_scene)_g · direct_g;
   * the indirect light is (1 − e)·I_from + e·I_scene exactly when both weights were solved (the
   * solution cache), otherwise the last solve scaled by Φ. Only the scene's own weights (the end of
   * the fade) are ever solved. Throws when `from` has other luminaires than the scene.
   */
  setFade(fade: EngineFade | null): void;
  /**
   * Which light the maps show (docs/daylight.md, "Daylight in the relight engine"): 'electric' (the
   * luminaire groups), 'daylight' (the sky and sun bases), 'both' (default) or 'daylight-factor'
   * (the windows under the CIE overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE alone: lux / 100 is
   * the DF in %; its basis is baked when first asked for). Otherwise weights only: no basis is rebaked; the indirect light is re-solved for the new weights (Φ-scaled meanwhile, or
   * at once from the solution cache when that choice was solved before). Throws on another value.
   */
  setLightSources(sources: LightSources): void;
  readonly lightSources: LightSources;
  /**
   * Advance pending work by one direct basis or up to `samples` indirect samples per texel; returns the progress.
   * With `preview` (default) the first solve of a room is read back and shown at most every PREVIEW_MS
   * (a re-solve keeps showing the previous solution, scaled, until it is done).
   */
  step(samples?: number, preview?: boolean): EngineProgress;
  /** Finish every pending bake and the solve now (for the CLI and tests). */
  finish(): void;
  readonly progress: EngineProgress;
  /** The relit maps for the current scene's weights (recomputed only when something changed). */
  maps(): LitMaps;
  /** The parts `maps()` would sum for the current weights (null before a scene); sums nothing, counts no relight. */
  relightParts(): RelightParts | null;
  /** Monotonic: bumps whenever `maps()` would return new values. */
  readonly version: number;
  readonly counters: EngineCounters;
  /**
   * The daylight bases kept out of the scene (daylightBasisCache.ts): how many, their bytes, the
   * budget (bytes) and the bases dropped for it so far. A room or objects change empties it.
   */
  readonly daylightCache: DaylightCacheStatus;
  readonly settings: BakeSettings;
  /**
   * Free the baker's pooled render targets (kept only to speed up the next bake; jobs under way
   * keep theirs): the bake service calls it on low-memory devices once the bake is done. The
   * bases and maps stay; the next bake allocates targets anew.
   */
  releaseTargets(): void;
  dispose(): void;
}
