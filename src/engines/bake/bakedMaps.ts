import type { Rgb, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { SURFACE_NAMES } from '../../core/model/lightingScene/lightingScene';
import type { SurfaceLayout } from './surfaceLayout';
import type { ObjectAtlas } from './objects/preparedObjects';

/**
 * Photometric value (lux) of an RGB light-map texel: the luminance weights of
 * linear sRGB/Rec. 709 primaries (IEC 61966-2-1), Y = 0.2126 R + 0.7152 G +
 * 0.0722 B. A white light (colour [1, 1, 1]) stores R = G = B = E, so Y = E.
 */
export const LUMINANCE_WEIGHTS: Rgb = [0.2126, 0.7152, 0.0722];

export interface SurfaceMaps {
  layout: SurfaceLayout;
  /** RGB lux, 3 floats per texel, row j = 0 (v = 0) first; see docs/baker.md. */
  direct: Float32Array;
  indirect: Float32Array;
  total: Float32Array;
}

/** The objects' light maps: one atlas for all objects (docs/baker.md, "Objects"), RGB lux per atlas texel; empty texels hold their dilated neighbours. */
export interface ObjectMaps {
  atlas: ObjectAtlas;
  direct: Float32Array;
  indirect: Float32Array;
  total: Float32Array;
}

/** One map set per room surface, and `objects` when the scene has objects. */
export type BakedMaps = Record<SurfaceName, SurfaceMaps> & { objects?: ObjectMaps };

/** Lux (Y) per texel of an RGB map. */
export function luxOf(rgb: Float32Array): Float32Array {
  const out = new Float32Array(rgb.length / 3);
  for (let i = 0; i < out.length; i++) {
    out[i] = LUMINANCE_WEIGHTS[0] * rgb[i * 3] + LUMINANCE_WEIGHTS[1] * rgb[i * 3 + 1] + LUMINANCE_WEIGHTS[2] * rgb[i * 3 + 2];
  }
  return out;
}

/**
 * Weighted sum of maps baked separately for groups of luminaires with the
 * same room and layout (light is linear: basis maps of each group, then any
 * dimming or colour per group without a new bake). A weight is a scalar or
 * an RGB multiplier. Exact for the direct maps; for the indirect maps up to
 * the Monte Carlo noise and the per-bake tail estimate (docs/baker.md).
 */
export function combineMaps(parts: { maps: BakedMaps; weight: number | Rgb }[]): BakedMaps {
  if (parts.length === 0) throw new Error('combineMaps needs at least one part');
  const first = parts[0].maps;
  const result = {} as BakedMaps;
  for (const name of SURFACE_NAMES) {
    const layout = first[name].layout;
    const size = layout.width * layout.height * 3;
    const sum = { direct: new Float32Array(size), indirect: new Float32Array(size), total: new Float32Array(size) };
    for (const { maps, weight } of parts) {
      const m = maps[name];
      if (m.layout.width !== layout.width || m.layout.height !== layout.height) {
        throw new Error(`combineMaps: ${name} maps differ in size (${m.layout.width}×${m.layout.height} vs ${layout.width}×${layout.height})`);
      }
      const w = typeof weight === 'number' ? [weight, weight, weight] : weight;
      for (const kind of ['direct', 'indirect', 'total'] as const) {
        const src = m[kind];
        const dst = sum[kind];
        for (let i = 0; i < size; i++) dst[i] += src[i] * w[i % 3];
      }
    }
    result[name] = { layout, ...sum };
  }
  // The objects' atlas, when the parts have one (every part of one scene has the same atlas).
  const atlas = first.objects?.atlas;
  if (atlas) {
    const size = atlas.width * atlas.height * 3;
    const sum = { direct: new Float32Array(size), indirect: new Float32Array(size), total: new Float32Array(size) };
    for (const { maps, weight } of parts) {
      const m = maps.objects;
      if (!m || m.total.length !== size) throw new Error(`combineMaps: objects maps differ in size (${m ? m.total.length / 3 : 'none'} vs ${size / 3} texels)`);
      const w = typeof weight === 'number' ? [weight, weight, weight] : weight;
      for (const kind of ['direct', 'indirect', 'total'] as const) {
        const src = m[kind];
        const dst = sum[kind];
        for (let i = 0; i < size; i++) dst[i] += src[i] * w[i % 3];
      }
    }
    result.objects = { atlas, ...sum };
  }
  return result;
}
