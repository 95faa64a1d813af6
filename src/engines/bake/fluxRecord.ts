import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS } from './bakedMaps';

/** Per recorded map set: flux-weighted reflectance per channel and the photometric flux (lm). */
export interface FluxRecord {
  ratio: Rgb;
  fluxY: number;
}

/** One surface's share of a record: Σ E over its texels per channel (lux), its texel area (m²) and reflectance. */
export interface SurfaceFlux {
  sum: Rgb;
  texelArea: number;
  reflectance: Rgb;
}

/**
 * Largest flux ratio recorded: the largest reflectance, and below 1 so that
 * the tail factor r/(1−r) (tailFactor.ts) stays finite.
 */
export function maxFluxRatio(reflectance: readonly Rgb[]): number {
  return Math.min(Math.max(...reflectance.flat()), 0.9999);
}

/**
 * The flux statistics of one set of maps (record k = bounce k), per channel c:
 *   Φ_c = Σ_s A_s·ΣE_s,c                    (flux arriving on all surfaces, lm)
 *   r_c = Σ_s ρ_s,c·A_s·ΣE_s,c / Φ_c        (flux-weighted reflectance)
 * with r clamped to [0, maxRatio] and Φ_Y = Y(Φ). In a closed box every
 * reflected lumen lands on a surface, so r is exactly the ratio Φ_{k+1}/Φ_k of
 * successive bounce fluxes that the tail needs (docs/baker.md, "Tail for
 * ρ → 1"). The bake computes the same on the GPU (shaders/fluxReduce.glsl.ts,
 * fluxStatistics.ts); this is its definition, checked without GL.
 */
export function fluxRecord(surfaces: readonly SurfaceFlux[], maxRatio: number): FluxRecord {
  const flux = [0, 0, 0];
  const reflected = [0, 0, 0];
  for (const s of surfaces) {
    for (let c = 0; c < 3; c++) {
      const f = s.sum[c] * s.texelArea;
      flux[c] += f;
      reflected[c] += f * s.reflectance[c];
    }
  }
  const ratio = flux.map((f, c) => (f > 0 ? Math.min(Math.max(reflected[c] / f, 0), maxRatio) : 0)) as Rgb;
  return { ratio, fluxY: flux.reduce((y, f, c) => y + f * LUMINANCE_WEIGHTS[c], 0) };
}
