/**
 * Small fixed passes (not generated per scene): combining maps and the
 * edge-aware blur. Each light map is its own texture and every read is
 * clamped to that texture, so nothing ever bleeds across a wall corner.
 */
import { fragmentHeader } from './fullscreen.glsl';

/** out = a·scaleA + b·scaleB (sum of bounce maps, tail, direct + indirect). */
export const combineFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uA;
uniform sampler2D uB;
uniform vec3 uScaleA;
uniform vec3 uScaleB;
out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 c = texelFetch(uA, p, 0).rgb * uScaleA + texelFetch(uB, p, 0).rgb * uScaleB;
  outColor = vec4(max(c, vec3(0.0)), 1.0);
}
`;

/**
 * One direction of a separable Gaussian. Taps outside this surface's texture
 * are dropped and the weights renormalised, instead of clamping (which would
 * over-weight the edge texel) or wrapping into a neighbour wall.
 */
export const blurFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uSource;
uniform ivec2 uDirection;
uniform int uRadius;
uniform float uInvTwoSigma2;
out vec4 outColor;
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
`;
