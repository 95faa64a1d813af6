/**
 * Flux statistics (fluxReduce.glsl.ts, docs/baker.md "Tail for ρ → 1") with the objects' atlas as a
 * seventh receiver. Atlas texels differ in area (coverage) and in reflectance (per texel), so the
 * atlas is reduced twice, weighted: Σ E·c and Σ ρ·E·c over blocks (c = coverage from the
 * G-buffer's point texture, ρ from its reflectance texture); the fused pass then adds
 * Φ_atlas = texel²·Σ E·c and its reflected part texel²·Σ ρ·E·c to the six walls' sums.
 */
import { fragmentPass } from './fragmentPass.glsl';
import { blockSumPass, fluxRatioSource, fluxRatioUniforms } from './fluxReduce.glsl';

/** out(p) = Σ over the uBlock² block at p of E·coverage, times ρ when uReflected = 1. */
export const objectReduceSumPass = blockSumPass(
  { uSource: 'sampler2D', uPoints: 'sampler2D', uRho: 'sampler2D', uBlock: 'int', uReflected: 'int' },
  (q) => `weighted(${q})`,
  /* glsl */ `vec3 weighted(ivec2 q) {
  vec3 e = texelFetch(uSource, q, 0).rgb * texelFetch(uPoints, q, 0).a;
  return uReflected == 1 ? e * texelFetch(uRho, q, 0).rgb : e;
}
`,
);

/** fluxRatioPass with the atlas: uSum6 = Σ E·c, uSum7 = Σ ρ·E·c (partial sums), uObjectArea = texel² × input scale. */
const objectFluxUniforms = { ...fluxRatioUniforms, uSum6: 'sampler2D', uSum7: 'sampler2D', uObjectArea: 'float' } as const;
const atlasStart = { flux: 'total(uSum6) * uObjectArea', reflected: 'total(uSum7) * uObjectArea' };
export const objectFluxRatioPass = fragmentPass(objectFluxUniforms, fluxRatioSource(atlasStart));
/** The same sums written as the reflected flux (R_R, R_G, R_B, Φ_Y): a room with openings (fluxReduce.glsl.ts seriesRatioPass). */
export const objectReflectedFluxPass = fragmentPass(objectFluxUniforms, fluxRatioSource(atlasStart, 'reflected'));
