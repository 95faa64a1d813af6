/**
 * out = a·scaleA + b·(uOffsetB + uTailB·f), f = r/(1−r) per channel with r
 * read from the flux-statistics row at uStatsIndex (fluxReduce.glsl.ts): the
 * tail of the bounce series applied without the CPU ever seeing r (in a room
 * with openings r is the measured R_k/R_{k−1}, seriesRatioPass; the same here). The same
 * factor on the CPU, with its derivation: src/engines/bake/tailFactor.ts.
 */
import { fragmentPass } from './fragmentPass.glsl';

export const combineTailPass = fragmentPass(
  { uA: 'sampler2D', uB: 'sampler2D', uStats: 'sampler2D', uStatsIndex: 'int', uScaleA: 'vec3', uOffsetB: 'vec3', uTailB: 'vec3' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 r = texelFetch(uStats, ivec2(uStatsIndex, 0), 0).rgb;
  vec3 f = r / (vec3(1.0) - r);
  vec3 c = texelFetch(uA, p, 0).rgb * uScaleA + texelFetch(uB, p, 0).rgb * (uOffsetB + uTailB * f);
  outColor = vec4(max(c, vec3(0.0)), 1.0);
}
`,
);
