import type { Rgb, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { readRgb, type FloatTarget } from '../bake/floatTarget';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';
import type { IndirectTerm, WeightedBasis } from './relightMaps';
import { initialGpuRelightState } from './gpuRelight/gpuRelightState';
import { relightGrid, relightReceivers } from './gpuRelight/combineRelight';
import { disposeRelightTextures, textureBytes } from './gpuRelight/relightTextures';

/** A receiver's display maps on the GPU: the direct and the total illuminance, RGBA32F render targets. */
export interface GpuDirectTotal {
  direct: FloatTarget;
  total: FloatTarget;
}

/** The display maps of every wall and, with objects, the atlas: textures the view samples directly. */
export type GpuLitMaps = Record<SurfaceName, GpuDirectTotal> & { objects?: GpuDirectTotal };

/** Precision of the basis and indirect textures: `float` (RGBA32F, 16 B/texel) or `half` (RGBA16F, 8 B/texel). */
export type BasisPrecision = 'float' | 'half';

/** GPU → CPU read-backs: how many and the bytes they moved (the viewer's `view3d().readbacks`). */
export interface ReadbackCounter {
  count: number;
  bytes: number;
}

export interface GpuRelight {
  /** The display maps for these weighted bases and indirect terms, combined on the GPU (no read-back). */
  relight(parts: readonly WeightedBasis[], terms: readonly IndirectTerm[], layouts: Readonly<Record<SurfaceName, SurfaceLayout>>, atlas: ObjectAtlas | null): GpuLitMaps;
  /**
   * A grid of any size combined like a receiver: Σ weight ⊙ map over `direct`, then plus Σ scale ⊙ map
   * over `indirect` (RGB per texel, row-major, `width` × `height`). The work plane's statistics use it
   * (workPlaneBases.ts). Its maps are uploaded once as RGBA32F whatever the precision (they are small,
   * and the statistics keep float accuracy) and kept while the next grid relight uses them.
   */
  relightGrid(key: string, width: number, height: number, direct: readonly GridPart[], indirect: readonly GridPart[]): GpuDirectTotal;
  /** One display map read back as RGB floats (3 per texel): counted in `readbacks`. Statistics and tests only. */
  read(target: FloatTarget): Float32Array;
  readonly readbacks: ReadbackCounter;
  /** CPU → GPU uploads of basis and indirect maps (each map once, while a relight uses it) and their bytes. */
  readonly uploads: ReadbackCounter;
  /** Draws of the combine pass so far. */
  readonly draws: number;
  /** Bytes of GPU texture memory held now: basis/indirect textures at their precision, display targets at 16 B/texel. */
  textureBytes(): number;
  dispose(): void;
}

/** One map of a grid relight and its per-channel factor. */
export interface GridPart {
  map: Float32Array;
  weight: Rgb;
}

/**
 * The relight of relightMaps.ts on the GPU (docs/viewer.md, "Relighting on the GPU"): the bases and
 * the indirect solutions are uploaded once as textures, and every relight (dimming, CCT, filters,
 * crossfade ends, DMX levels: only the weights and scales change) is a few full-screen draws per
 * receiver of relightCombine.glsl.ts into display targets the view samples. Nothing is read back.
 * The weights and the indirect terms (exact, crossfade blend, or the interim Φ_now/Φ_solve scale of
 * indirectTerms.ts) are the CPU relight's, so both show the same light.
 *
 * Its parts share one GpuRelightState (gpuRelight/gpuRelightState.ts): the uploads and targets
 * (gpuRelight/relightTextures.ts) and the combine draws (gpuRelight/combineRelight.ts).
 */
export function createGpuRelight(gl: WebGL2RenderingContext, precision: BasisPrecision = 'float'): GpuRelight {
  const s = initialGpuRelightState(gl, precision);
  return {
    relight: (parts, terms, layouts, atlas) => relightReceivers(s, parts, terms, layouts, atlas),
    relightGrid: (key, width, height, direct, indirect) => relightGrid(s, key, width, height, direct, indirect),
    read(target) {
      s.readbacks.count++;
      s.readbacks.bytes += target.width * target.height * 16;
      return readRgb(gl, target);
    },
    readbacks: s.readbacks,
    uploads: s.uploaded,
    get draws() {
      return s.draws;
    },
    textureBytes: () => textureBytes(s),
    dispose: () => disposeRelightTextures(s),
  };
}
