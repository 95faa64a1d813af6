/**
 * Flux statistics (fluxReduce.glsl.ts, docs/baker.md "Tail for ρ → 1") with the objects' atlas as a
 * seventh receiver. Atlas texels differ in area (coverage) and in reflectance (per texel), so the
 * atlas is reduced twice, weighted: Σ E·c and Σ ρ·E·c over blocks (c = coverage from the
 * G-buffer's point texture, ρ from its reflectance texture); the fused pass then adds
 * Φ_atlas = texel²·Σ E·c and its reflected part texel²·Σ ρ·E·c to the six walls' sums.
 */
import { fragmentPass } from './fragmentPass.glsl';

/** out(p) = Σ over the uBlock² block at p of E·coverage, times ρ when uReflected = 1. */
export const objectReduceSumPass = fragmentPass(
  { uSource: 'sampler2D', uPoints: 'sampler2D', uRho: 'sampler2D', uBlock: 'int', uReflected: 'int' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 size = textureSize(uSource, 0);
  ivec2 base = ivec2(gl_FragCoord.xy) * uBlock;
  ivec2 end = min(base + ivec2(uBlock), size);
  vec3 sum = vec3(0.0);
  for (int j = base.y; j < end.y; j++) {
    for (int i = base.x; i < end.x; i++) {
      ivec2 q = ivec2(i, j);
      vec3 e = texelFetch(uSource, q, 0).rgb * texelFetch(uPoints, q, 0).a;
      sum += uReflected == 1 ? e * texelFetch(uRho, q, 0).rgb : e;
    }
  }
  outColor = vec4(sum, 1.0);
}
`,
);

/** fluxRatioPass with the atlas: uSum6 = Σ E·c, uSum7 = Σ ρ·E·c (partial sums), uObjectArea = texel² × input scale. */
export const objectFluxRatioPass = fragmentPass(
  {
    uSum0: 'sampler2D',
    uSum1: 'sampler2D',
    uSum2: 'sampler2D',
    uSum3: 'sampler2D',
    uSum4: 'sampler2D',
    uSum5: 'sampler2D',
    uSum6: 'sampler2D',
    uSum7: 'sampler2D',
    uArea: 'float[6]',
    uRho: 'vec3[6]',
    uObjectArea: 'float',
    uMaxRatio: 'float',
    uLuminance: 'vec3',
  },
  /* glsl */ `out vec4 outColor;
vec3 total(sampler2D partial) {
  ivec2 size = textureSize(partial, 0);
  vec3 sum = vec3(0.0);
  for (int j = 0; j < size.y; j++) {
    for (int i = 0; i < size.x; i++) sum += texelFetch(partial, ivec2(i, j), 0).rgb;
  }
  return sum;
}
void main() {
  vec3 e[6];
  e[0] = total(uSum0);
  e[1] = total(uSum1);
  e[2] = total(uSum2);
  e[3] = total(uSum3);
  e[4] = total(uSum4);
  e[5] = total(uSum5);
  vec3 flux = total(uSum6) * uObjectArea;
  vec3 reflected = total(uSum7) * uObjectArea;
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
`,
);
