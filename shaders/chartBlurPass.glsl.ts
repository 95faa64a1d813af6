/**
 * One direction of the separable Gaussian (blurPass.glsl.ts) for the objects' atlas: a tap counts
 * only if it is covered and lies in the same chart as the centre texel (uCharts: the G-buffer's
 * normal texture, a = chart id + 1, 0 = empty); other taps are dropped and the weights
 * renormalised. So no light bleeds between charts that are neighbours in the atlas but not on the
 * objects (a table top and a chair seat), nor across a chart's edge into empty texels, and a
 * uniform field stays uniform. Empty texels stay 0 (the dilation pass fills them afterwards).
 */
import { fragmentPass } from './fragmentPass.glsl';

export const chartBlurPass = fragmentPass(
  { uSource: 'sampler2D', uCharts: 'sampler2D', uDirection: 'ivec2', uRadius: 'int', uInvTwoSigma2: 'float' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uSource, 0);
  float chart = texelFetch(uCharts, p, 0).a;
  if (chart <= 0.0) {
    outColor = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int k = -uRadius; k <= uRadius; k++) {
    ivec2 q = p + uDirection * k;
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
    if (texelFetch(uCharts, q, 0).a != chart) continue;
    float w = exp(-float(k * k) * uInvTwoSigma2);
    sum += w * texelFetch(uSource, q, 0).rgb;
    weight += w;
  }
  outColor = vec4(sum / weight, 1.0);
}
`,
);
