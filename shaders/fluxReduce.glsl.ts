/**
 * GPU reduction of the light maps to the few numbers the tail estimate needs
 * (docs/baker.md, "Tail for ρ → 1"). Reading whole maps back to the CPU after
 * every bounce stalls the pipeline; these passes reduce each map to at most
 * REDUCE_GRID² partial sums and then to one stats texel per bounce, which
 * stays on the GPU until a caller asks for the report.
 */
import { fragmentPass, type FragmentPass, type UniformSpec } from './fragmentPass.glsl';

/**
 * Largest edge of the first reduction level: a map is summed in blocks of
 * ⌈max(w, h)/REDUCE_GRID⌉² texels to at most REDUCE_GRID² partial sums, and
 * the fused final pass adds those up for all six surfaces. Two passes per
 * record (6 + 1 draws) instead of a log₄ chain: per-draw overhead, not
 * arithmetic, dominates these tiny passes on a GPU (docs/benchmarks.md).
 */
export const REDUCE_GRID = 16;

/**
 * The first reduction level of any map: out(p) = Σ over the uBlock² block of uSource at p
 * (clipped to uSource) of `texelValue(q)`, a GLSL expression of the texel q; `helpers`: GLSL the
 * expression calls, declared before main. One block sum for the walls (the texel itself) and the
 * objects' atlas (weighted by coverage and ρ: objectFluxReduce.glsl.ts).
 */
export function blockSumPass<U extends UniformSpec & { uSource: 'sampler2D'; uBlock: 'int' }>(uniforms: U, texelValue: (q: string) => string, helpers = ''): FragmentPass<U> {
  return fragmentPass(
    uniforms,
    /* glsl */ `${helpers}out vec4 outColor;
void main() {
  ivec2 size = textureSize(uSource, 0);
  ivec2 base = ivec2(gl_FragCoord.xy) * uBlock;
  ivec2 end = min(base + ivec2(uBlock), size);
  vec3 sum = vec3(0.0);
  for (int j = base.y; j < end.y; j++) {
    for (int i = base.x; i < end.x; i++) sum += ${texelValue('ivec2(i, j)')};
  }
  outColor = vec4(sum, 1.0);
}
`,
  );
}

/** out(p) = Σ source texels of the uBlock² block at p (clipped to the source). */
export const reduceSumPass = blockSumPass({ uSource: 'sampler2D', uBlock: 'int' }, (q) => `texelFetch(uSource, ${q}, 0).rgb`);

/**
 * From the six first-level partial sums (at most REDUCE_GRID² texels each),
 * per channel c:
 *   Φ_c = Σ_s A_s·ΣE_s,c  (flux, lm, with A_s the texel area × input scale)
 *   r_c = Σ_s ρ_s,c·A_s·ΣE_s,c / Φ_c, clamped to [0, uMaxRatio]
 * written as (r_R, r_G, r_B, Φ_Y) into one texel of the stats row (the
 * draw's viewport picks which). The same formula on the CPU, and why r is
 * what the tail needs: src/engines/bake/fluxRecord.ts.
 *
 * Its uniforms (the object variant adds its atlas sums: objectFluxReduce.glsl.ts):
 */
export const fluxRatioUniforms = {
  uSum0: 'sampler2D',
  uSum1: 'sampler2D',
  uSum2: 'sampler2D',
  uSum3: 'sampler2D',
  uSum4: 'sampler2D',
  uSum5: 'sampler2D',
  uArea: 'float[6]',
  uRho: 'vec3[6]',
  uMaxRatio: 'float',
  uLuminance: 'vec3',
} as const;

/**
 * The flux-ratio pass's GLSL, the six surfaces' sums added to `start` (the atlas's flux and
 * reflected flux for a scene with objects, zero otherwise): one formula for both passes.
 * `output` 'ratio' writes (r_R, r_G, r_B, Φ_Y); 'reflected' writes the reflected flux itself
 * (R_R, R_G, R_B, Φ_Y), which a room with openings keeps per bounce for seriesRatioPass.
 */
export function fluxRatioSource(start: { flux: string; reflected: string }, output: 'ratio' | 'reflected' = 'ratio'): string {
  const write =
    output === 'ratio'
      ? /* glsl */ `vec3 ratio = vec3(0.0);
  for (int c = 0; c < 3; c++) {
    if (flux[c] > 0.0) ratio[c] = clamp(reflected[c] / flux[c], 0.0, uMaxRatio);
  }
  outColor = vec4(ratio, dot(flux, uLuminance));`
      : /* glsl */ `outColor = vec4(reflected, dot(flux, uLuminance));`;
  return /* glsl */ `out vec4 outColor;
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
  vec3 flux = ${start.flux};
  vec3 reflected = ${start.reflected};
  for (int s = 0; s < 6; s++) {
    vec3 f = e[s] * uArea[s];
    flux += f;
    reflected += f * uRho[s];
  }
  ${write}
}
`;
}

export const fluxRatioPass = fragmentPass(fluxRatioUniforms, fluxRatioSource({ flux: 'vec3(0.0)', reflected: 'vec3(0.0)' }));

/**
 * The tail's ratio in a room with openings (docs/baker.md, "Tail for ρ → 1"): there part of each
 * bounce's reflected flux leaves through the openings, so the flux-weighted reflectance
 * overestimates the next bounce; the measured ratio of successive reflected fluxes does not:
 *   r_c = R_c,k / R_c,k−1,  R_c,k = Σ ρ·E_k·A over the room's surfaces (bounce k),
 * clamped to [0, uMaxRatio], read from the 'reflected' row (fluxRatioSource) at uIndex and
 * uIndex − 1 and written with that record's Φ_Y. The same on the CPU: src/engines/bake/fluxRecord.ts.
 */
export const seriesRatioPass = fragmentPass(
  { uReflected: 'sampler2D', uIndex: 'int', uMaxRatio: 'float' },
  /* glsl */ `out vec4 outColor;
void main() {
  vec4 now = texelFetch(uReflected, ivec2(uIndex, 0), 0);
  vec3 before = texelFetch(uReflected, ivec2(uIndex - 1, 0), 0).rgb;
  vec3 ratio = vec3(0.0);
  for (int c = 0; c < 3; c++) {
    if (before[c] > 0.0) ratio[c] = clamp(now[c] / before[c], 0.0, uMaxRatio);
  }
  outColor = vec4(ratio, now.a);
}
`,
);
