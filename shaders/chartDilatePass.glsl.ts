/**
 * Dilation of the objects' atlas maps: a covered texel keeps its value; an empty texel within
 * 2 texels (Chebyshev distance) of a covered one takes the mean of the covered texels of the
 * nearest ring (distance 1, else 2) around it. Bilinear lookups at a chart's border (the viewer's
 * texture filtering) then blend the chart's own values instead of black. Texels farther than
 * 2 from every chart stay 0; the packer keeps charts ≥ 2 texels apart (docs/baker.md, "Objects:
 * geometry"), so a gutter texel may take values from both neighbours, never a covered one.
 */
import { fragmentPass } from './fragmentPass.glsl';

export const chartDilatePass = fragmentPass(
  { uSource: 'sampler2D', uCoverage: 'sampler2D' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  ivec2 size = textureSize(uSource, 0);
  if (texelFetch(uCoverage, p, 0).a > 0.0) {
    outColor = vec4(texelFetch(uSource, p, 0).rgb, 1.0);
    return;
  }
  for (int r = 1; r <= 2; r++) {
    vec3 sum = vec3(0.0);
    float count = 0.0;
    for (int j = -r; j <= r; j++) {
      for (int i = -r; i <= r; i++) {
        if (max(abs(i), abs(j)) != r) continue;
        ivec2 q = p + ivec2(i, j);
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        if (texelFetch(uCoverage, q, 0).a <= 0.0) continue;
        sum += texelFetch(uSource, q, 0).rgb;
        count += 1.0;
      }
    }
    if (count > 0.0) {
      outColor = vec4(sum / count, 1.0);
      return;
    }
  }
  outColor = vec4(0.0, 0.0, 0.0, 1.0);
}
`,
);
