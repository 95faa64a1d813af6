import type { Rgb, SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import { texelArea } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';

/**
 * Reflected direct flux per channel, Φ_c = Σ over every receiver of ρ_c · E_c · A (lm): the light
 * the direct maps send into the first bounce. Walls: ρ of the surface, A the texel area; the
 * objects' atlas: ρ per texel (the G-buffer's reflectance) and A = coverage × texel² (the same
 * weighting as the bake's flux statistics, fluxStatistics.ts / shaders/objectFluxReduce.glsl.ts).
 * `atlasDirect` is the atlas's emitted direct map (uncovered texels weigh 0 either way).
 */
export function reflectedFlux(surfaces: Record<SurfaceName, Float32Array>, layouts: readonly SurfaceLayout[], reflectance: Record<SurfaceName, Rgb>, atlas: ObjectAtlas | null = null, atlasDirect: Float32Array | null = null): Rgb {
  const flux: Rgb = [0, 0, 0];
  for (const layout of layouts) {
    const e = surfaces[layout.name];
    const sum = [0, 0, 0];
    for (let i = 0; i < e.length; i += 3) {
      sum[0] += e[i];
      sum[1] += e[i + 1];
      sum[2] += e[i + 2];
    }
    const area = texelArea(layout);
    const rho = reflectance[layout.name];
    for (let c = 0; c < 3; c++) flux[c] += rho[c] * area * sum[c];
  }
  if (atlas && atlasDirect) {
    const texel2 = atlas.texelSize * atlas.texelSize;
    const { position, reflectance: rho } = atlas;
    for (let t = 0, n = atlas.width * atlas.height; t < n; t++) {
      const coverage = position[t * 4 + 3];
      if (coverage <= 0) continue;
      const a = coverage * texel2;
      for (let c = 0; c < 3; c++) flux[c] += rho[t * 4 + c] * a * atlasDirect[t * 3 + c];
    }
  }
  return flux;
}

/** Σ_g w_g ⊙ Φ_g: Φ is linear in the direct maps, so the flux of any weighting comes from the groups' own. */
export function weightedFlux(parts: readonly { flux: Rgb; weight: Rgb }[]): Rgb {
  const out: Rgb = [0, 0, 0];
  for (const { flux, weight } of parts) for (let c = 0; c < 3; c++) out[c] += weight[c] * flux[c];
  return out;
}

/**
 * Per channel Φ_now / Φ_solve: the factor the last indirect solution is shown with until the
 * re-solve at the current weights is done. Φ_solve = 0 (everything was off, or nothing
 * reflects) gives 0, never NaN or ∞: no indirect light is shown until the re-solve.
 */
export function indirectScale(now: Rgb, solved: Rgb): Rgb {
  return [0, 1, 2].map((c) => (solved[c] > 0 ? now[c] / solved[c] : 0)) as Rgb;
}
