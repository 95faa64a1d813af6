/**
 * The illuminance statistics on the GPU (docs/viewer.md, "Statistics on the GPU"): a map is reduced
 * to (ΣY, count, Ymin, Ymax) of its counted texels, Y = photometric luminance weights · RGB lux (the
 * same LUMINANCE_WEIGHTS as lightStats.ts), in two passes as fluxReduce.glsl.ts does: blocks of
 * uBlock² texels to at most STATS_GRID² partials, then the partials to one texel. A texel counts
 * where the mask's red channel is 1 (the floor under furniture is left out, floorUnderObjects).
 */
import { fragmentPass } from './fragmentPass.glsl';

/** Largest edge of the partials: a 256² map is read in 16² blocks of 16² texels. */
export const STATS_GRID = 16;

/** No texel in a block: min and max start at ±3e38, so they lose every comparison (createGpuStats clears the partials to the same). */
const FLOAT_BIG = '3.0e38';

export const statsBlockPass = fragmentPass(
  { uSource: 'sampler2D', uMask: 'sampler2D', uBlock: 'int', uLuminance: 'vec3' } as const,
  /* glsl */ `out vec4 outStats;
void main() {
  ivec2 size = textureSize(uSource, 0);
  ivec2 base = ivec2(gl_FragCoord.xy) * uBlock;
  ivec2 end = min(base + ivec2(uBlock), size);
  vec4 s = vec4(0.0, 0.0, ${FLOAT_BIG}, -${FLOAT_BIG});
  for (int j = base.y; j < end.y; j++) {
    for (int i = base.x; i < end.x; i++) {
      if (texelFetch(uMask, ivec2(i, j), 0).r < 0.5) continue;
      float y = dot(texelFetch(uSource, ivec2(i, j), 0).rgb, uLuminance);
      s.xy += vec2(y, 1.0);
      s.z = min(s.z, y);
      s.w = max(s.w, y);
    }
  }
  outStats = s;
}
`,
);

export const statsMergePass = fragmentPass(
  { uSource: 'sampler2D' } as const,
  /* glsl */ `out vec4 outStats;
void main() {
  ivec2 size = textureSize(uSource, 0);
  vec4 s = vec4(0.0, 0.0, ${FLOAT_BIG}, -${FLOAT_BIG});
  for (int j = 0; j < size.y; j++) {
    for (int i = 0; i < size.x; i++) {
      vec4 p = texelFetch(uSource, ivec2(i, j), 0);
      s.xy += p.xy;
      s.z = min(s.z, p.z);
      s.w = max(s.w, p.w);
    }
  }
  outStats = s;
}
`,
);
