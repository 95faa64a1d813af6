import type { Rgb, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakedMaps } from './bakedMaps';
import type { BakeObject, BakeScene } from './bakeScene';
import type { BakeSettings } from './bakeSettings';
import type { SurfaceLayout } from './surfaceLayout';
import type { ObjectReportEntry } from './objects/objectPassReport';
import type { ObjectAtlas } from './objects/preparedObjects';

/** The baker's public contract: what createBaker returns, its jobs, their progress and reports. */
export interface BakeProgress {
  /** Bounces finished. */
  bounce: number;
  bounces: number;
  /** Samples gathered so far in the bounce under way. */
  samplesDone: number;
  samplesPerBounce: number;
  done: boolean;
}

export interface BakeReport {
  settings: BakeSettings;
  texels: Record<SurfaceName, [number, number]>;
  totalTexels: number;
  luminaires: number;
  pointSources: number;
  /** Surfaces no luminaire can reach: their direct pass was skipped. */
  directSkipped: SurfaceName[];
  indirectEnabled: boolean;
  /** Bright patches gathered exactly in bounce 1 (docs/baker.md) and the peakedness S·ΣM²A/(ΣMA)² of the exitance before and after taking them out. */
  brightPatches?: { count: number; peakedness: number; residualPeakedness: number };
  samplesPerTexelPerBounce: number;
  bouncesComputed: number;
  /** Flux (lm, photometric Y) arriving on all surfaces: [direct, bounce 1, bounce 2, ...]. */
  bounceFlux: number[];
  /** Flux-weighted reflectance of the last computed bounce per channel, and the tail factor r/(1−r) applied. */
  tailRatio: Rgb;
  tailFactor: Rgb;
  linearFiltering: boolean;
  shaders: { pass: string; surface: SurfaceName | null; bytes: number; cached: boolean }[];
  timings_ms: { compile: number; direct: number; indirect: number; blur: number; blend: number; readback: number; total: number };
  /** GPU → CPU read-backs this job made (readPixels calls) and the bytes they moved: 0 until the caller reads maps or this report. */
  readbacks: { count: number; bytes: number };
  /** Per object (scenes with objects only; docs/scene-format.md): area, atlas texels, total lux mean/min/max and flux. */
  objects?: ObjectReportEntry[];
  /** Scenes with daylight through windows only (docs/daylight.md, "The baker"): the windows, the CPU time of the direct daylight and its flux on the room's surfaces and objects (lm, Y) split into sky (with the ground) and sun. */
  daylight?: { windows: number; directMs: number; skyFlux: number; sunFlux: number };
}

/** A receiver's maps on the GPU. */
export interface MapTextures {
  direct: WebGLTexture;
  indirect: WebGLTexture;
  total: WebGLTexture;
}

/**
 * A bake's direct maps only (RGB lux, 3 floats per texel, row j = 0 first): what a relighting
 * basis keeps (docs/viewer.md, "Relighting without rebaking"). With objects, the atlas's direct
 * map twice: `emitted` as the bounces read it (covered texels only, as the direct pass wrote it;
 * what startFromDirect takes back) and `shown`, dilated into the charts' gutters like every map
 * the viewer displays (shaders/chartDilatePass.glsl.ts).
 */
export interface DirectMaps {
  surfaces: Record<SurfaceName, Float32Array>;
  objects?: { atlas: ObjectAtlas; emitted: Float32Array; shown: Float32Array };
}

/** A scene's objects for an indirect-only solve: the objects and their atlas's direct map (DirectMaps.objects.emitted, in the atlas prepareObjects gives for the solve's settings). */
export interface GivenObjectDirect {
  /** Pass the scene's own array: the prepared atlas and BVH are cached per array (prepareObjectsCached). */
  objects: BakeObject[];
  direct: Float32Array;
}

/** A bake in progress: direct maps ready, indirect refined by `step` (for the browser, a few samples per frame). */
export interface BakeJob {
  readonly layouts: SurfaceLayout[];
  readonly progress: BakeProgress;
  /** Gather up to `samples` more indirect samples per texel (default: settings.samplesPerDraw). */
  step(samples?: number): BakeProgress;
  /** Step until every bounce is done, then finalize. */
  run(): void;
  /** Build indirect (blurred, with the tail estimate) and total maps from the current state. */
  finalize(): void;
  /** Current maps on the GPU (valid until dispose), e.g. for the viewer. Call finalize first. */
  textures(): Record<SurfaceName, MapTextures> & { objects?: MapTextures };
  /** Maps read back as RGB lux floats (finalizes if needed). */
  readMaps(): BakedMaps;
  /** The direct maps only (finalizes if needed; 6 read-backs, 8 with objects, instead of readMaps' 18 or 21). */
  readDirect(): DirectMaps;
  report(): BakeReport;
  dispose(): void;
}

export interface Baker {
  /** Start a bake: runs the direct pass now, returns the job for the indirect passes. */
  start(scene: BakeScene, settings?: Partial<BakeSettings>): BakeJob;
  /**
   * Start an indirect-only solve from given per-surface "direct" maps (RGB,
   * 3 floats per texel, layouts as `surfaceLayouts` gives for these settings):
   * e.g. uniform self-emission for the grey-furnace check, or an external
   * direct solution (the relight engine's shared indirect solve: Σ weight · direct basis).
   * With `objects`, the objects shade and bounce as in `start`, and their atlas emits the given
   * atlas direct map; without, the empty room exactly as before.
   */
  startFromDirect(room: BakeScene['room'], direct: Record<SurfaceName, Float32Array>, settings?: Partial<BakeSettings>, objects?: GivenObjectDirect): BakeJob;
  /** Free the render targets kept for the next bake (jobs still running keep theirs until disposed). */
  dispose(): void;
  /** start + run + readMaps + report. */
  bake(scene: BakeScene, settings?: Partial<BakeSettings>): { maps: BakedMaps; report: BakeReport };
}
