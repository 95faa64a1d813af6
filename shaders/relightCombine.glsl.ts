/**
 * The viewer's relight on the GPU (docs/viewer.md, "Relighting on the GPU"): one texel of a
 * display map is `uAccum + Σ_k uWeight[k] ⊙ basis_k`, per channel, for up to
 * RELIGHT_BASES_PER_DRAW bases per draw. The direct map is Σ_g w_g ⊙ direct_g (uAccum a zero
 * texture); the total map is the direct map plus Σ_k s_k ⊙ indirect_k (uAccum the direct map).
 * Terms are added one after another in the order given, as relightMaps.ts does on the CPU, so both
 * round the same way up to the last bit of a float32 multiply-add.
 */
import { fragmentPass } from './fragmentPass.glsl';

/** Bases summed by one draw: 8 samplers + the accumulator stay within WebGL2's minimum of 16 fragment texture units. */
export const RELIGHT_BASES_PER_DRAW = 8;

const uniforms = {
  uAccum: 'sampler2D',
  uB0: 'sampler2D',
  uB1: 'sampler2D',
  uB2: 'sampler2D',
  uB3: 'sampler2D',
  uB4: 'sampler2D',
  uB5: 'sampler2D',
  uB6: 'sampler2D',
  uB7: 'sampler2D',
  uWeight: `vec3[${RELIGHT_BASES_PER_DRAW}]`,
  uCount: 'int',
} as const;

export type RelightCombineUniforms = typeof uniforms;

/** The basis samplers by index (uB0 … uB7). */
export const RELIGHT_BASIS_SAMPLERS = ['uB0', 'uB1', 'uB2', 'uB3', 'uB4', 'uB5', 'uB6', 'uB7'] as const;

export const relightCombinePass = fragmentPass(
  uniforms,
  /* glsl */ `
out vec4 fragColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 sum = texelFetch(uAccum, p, 0).rgb;
  // Unrolled: sampler arrays may only be indexed by constants in GLSL ES 3.00.
  if (uCount > 0) sum += texelFetch(uB0, p, 0).rgb * uWeight[0];
  if (uCount > 1) sum += texelFetch(uB1, p, 0).rgb * uWeight[1];
  if (uCount > 2) sum += texelFetch(uB2, p, 0).rgb * uWeight[2];
  if (uCount > 3) sum += texelFetch(uB3, p, 0).rgb * uWeight[3];
  if (uCount > 4) sum += texelFetch(uB4, p, 0).rgb * uWeight[4];
  if (uCount > 5) sum += texelFetch(uB5, p, 0).rgb * uWeight[5];
  if (uCount > 6) sum += texelFetch(uB6, p, 0).rgb * uWeight[6];
  if (uCount > 7) sum += texelFetch(uB7, p, 0).rgb * uWeight[7];
  fragColor = vec4(sum, 1.0);
}
`,
);
