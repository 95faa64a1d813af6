/**
 * One direction of a separable Gaussian. Taps outside this surface's texture
 * are dropped and the weights renormalised, instead of clamping (which would
 * over-weight the edge texel) or wrapping into a neighbour wall; a uniform
 * field stays exactly uniform.
 */
import { fragmentPass } from './fragmentPass.glsl';

export const blurPass = fragmentPass(
  { uSource: 'sampler2D', uDirection: 'ivec2', uRadius: 'int', uInvTwoSigma2: 'float' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uSource, 0);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int k = -uRadius; k <= uRadius; k++) {
    ivec2 q = p + uDirection * k;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    float w = exp(-float(k * k) * uInvTwoSigma2);
    sum += w * texelFetch(uSource, q, 0).rgb;
    weight += w;
  }
  outColor = vec4(sum / weight, 1.0);
}
`,
);
