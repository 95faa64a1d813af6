import type { Rgb } from '../../core/model/lightingScene/lightingScene';

/**
 * Tail of the bounce series (ρ → 1), per channel. In a closed box every
 * reflected lumen lands on some surface, so the flux of bounce k+1 is exactly
 * the reflected flux of bounce k: Φ_{k+1} = Σ ρ·E_k·A. The ratio r = Φ_{k+1}/Φ_k
 * is the flux-weighted reflectance of bounce k (fluxRecord.ts), and as k grows
 * the bounce shape converges (power iteration) so r becomes constant: the
 * remaining series is geometric, Σ_{j>B} E_j ≈ E_B · r/(1−r). This is the
 * "ambient term" of progressive radiosity (Cohen, Chen, Wallace & Greenberg,
 * SIGGRAPH 1988), applied with E_B's own distribution as the shape. For a
 * uniform reflectance it makes the total exact in expectation: the mean of
 * E_0 + … + E_B + E_B·f is Φ/(S(1−ρ)), the integrating-sphere value.
 * In a room with openings part of each bounce's reflected flux leaves, so
 * Φ_{k+1} < Σ ρ·E_k·A and the ratio is measured instead, r = R_k/R_{k−1} of
 * successive reflected fluxes (fluxRecord.ts openRoomRecord): ρ(1 − f) of the
 * integrating sphere with a port of share f, whose absorbed flux
 * Φ_in(1−ρ)/(1−ρ(1−f)) the same geometric sum gives.
 * The bake applies f on the GPU (shaders/combineTailPass.glsl.ts); the report
 * states it from here.
 */
export function tailFactor(ratio: Rgb): Rgb {
  return ratio.map((r) => r / (1 - r)) as Rgb;
}
