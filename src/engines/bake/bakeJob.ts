import type { Rgb, SurfaceName } from '../../core/model/lightingScene';
import type { BakedMaps } from './bakedMaps';
import type { BakeScene } from './bakeScene';
import type { BakeSettings } from './bakeSettings';
import type { SurfaceLayout } from './surfaceLayout';
import type { ObjectReportEntry } from './objects/objectPassReport';

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
}

/** A receiver's maps on the GPU. */
export interface MapTextures {
  direct: WebGLTexture;
  indirect: WebGLTexture;
  total: WebGLTexture;
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
   * direct solution.
   */
  startFromDirect(room: BakeScene['room'], direct: Record<SurfaceName, Float32Array>, settings?: Partial<BakeSettings>): BakeJob;
  /** Free the render targets kept for the next bake (jobs still running keep theirs until disposed). */
  dispose(): void;
  /** start + run + readMaps + report. */
  bake(scene: BakeScene, settings?: Partial<BakeSettings>): { maps: BakedMaps; report: BakeReport };
}
