/**
 * GPU reduction of the light maps to the few numbers the tail estimate needs
 * (docs/baker.md, "Flux statistics on the GPU"). Reading whole maps back to
 * the CPU after every bounce stalls the pipeline; these passes reduce each map
 * to one texel and then to one stats texel per bounce, which stays on the GPU
 * until a caller asks for the report.
 */
import { fragmentHeader } from './fullscreen.glsl';

/** Edge of the block one reduction texel sums (a 256² map reaches 1×1 in four passes). */
export const REDUCE_FACTOR = 4;

/**
 * out(p) = Σ source texels of the REDUCE_FACTOR² block at p (clipped to the
 * source): a plain sum, so the last level holds Σ E over the whole map.
 */
export const reduceSumFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uSource;
out vec4 outColor;
void main() {
  ivec2 size = textureSize(uSource, 0);
  ivec2 base = ivec2(gl_FragCoord.xy) * ${REDUCE_FACTOR};
  vec3 sum = vec3(0.0);
  for (int j = 0; j < ${REDUCE_FACTOR}; j++) {
    for (int i = 0; i < ${REDUCE_FACTOR}; i++) {
      ivec2 q = base + ivec2(i, j);
      if (q.x < size.x && q.y < size.y) sum += texelFetch(uSource, q, 0).rgb;
    }
  }
  outColor = vec4(sum, 1.0);
}
`;

/**
 * From the six per-surface sums Σ E (1×1 textures), per channel c:
 *   Φ_c = Σ_s A_s·ΣE_s,c  (flux, lm, with A_s the texel area × input scale)
 *   r_c = Σ_s ρ_s,c·A_s·ΣE_s,c / Φ_c, clamped to [0, min(max ρ, 0.9999)]
 * written as (r_R, r_G, r_B, Φ_Y) into one texel of the stats row (the
 * draw's viewport picks which). Same formula as the CPU reference of
 * fluxStatistics.ts; r is the flux-weighted reflectance that the tail
 * r/(1−r) uses.
 */
export const fluxRatioFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uSum0;
uniform sampler2D uSum1;
uniform sampler2D uSum2;
uniform sampler2D uSum3;
uniform sampler2D uSum4;
uniform sampler2D uSum5;
uniform float uArea[6];
uniform vec3 uRho[6];
uniform float uMaxRatio;
uniform vec3 uLuminance;
out vec4 outColor;
void main() {
  vec3 e[6];
  e[0] = texelFetch(uSum0, ivec2(0), 0).rgb;
  e[1] = texelFetch(uSum1, ivec2(0), 0).rgb;
  e[2] = texelFetch(uSum2, ivec2(0), 0).rgb;
  e[3] = texelFetch(uSum3, ivec2(0), 0).rgb;
  e[4] = texelFetch(uSum4, ivec2(0), 0).rgb;
  e[5] = texelFetch(uSum5, ivec2(0), 0).rgb;
  vec3 flux = vec3(0.0);
  vec3 reflected = vec3(0.0);
  for (int s = 0; s < 6; s++) {
    vec3 f = e[s] * uArea[s];
    flux += f;
    reflected += f * uRho[s];
  }
  vec3 ratio = vec3(0.0);
  for (int c = 0; c < 3; c++) {
    if (flux[c] > 0.0) ratio[c] = clamp(reflected[c] / flux[c], 0.0, uMaxRatio);
  }
  outColor = vec4(ratio, dot(flux, uLuminance));
}
`;

/**
 * out = a·scaleA + b·(uOffsetB + uTailB·f), f = r/(1−r) per channel with r
 * read from the stats row at uStatsIndex: the tail of the bounce series
 * applied without the CPU ever seeing r.
 */
export const combineTailFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uA;
uniform sampler2D uB;
uniform sampler2D uStats;
uniform int uStatsIndex;
uniform vec3 uScaleA;
uniform vec3 uOffsetB;
uniform vec3 uTailB;
out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 r = texelFetch(uStats, ivec2(uStatsIndex, 0), 0).rgb;
  vec3 f = r / (vec3(1.0) - r);
  vec3 c = texelFetch(uA, p, 0).rgb * uScaleA + texelFetch(uB, p, 0).rgb * (uOffsetB + uTailB * f);
  outColor = vec4(max(c, vec3(0.0)), 1.0);
}
`;
