/**
 * The illuminance statistics on the GPU (docs/viewer.md, "Statistics on the GPU"): a map is reduced
 * to (Σ w·Y, Σ w, Ymin, Ymax) of its counted texels, Y = photometric luminance weights · RGB lux (the
 * same LUMINANCE_WEIGHTS as lightStats.ts), in two passes as fluxReduce.glsl.ts does: blocks of
 * uBlock² texels to at most STATS_GRID² partials, then the partials to one texel. A texel counts
 * with the weight w in the mask's red channel where it is above 0: 1 or 0 on a box room's floor (the
 * floor under furniture is left out, floorUnderObjects), a texel's coverage on a shaped room's floor
 * in the atlas (roomSurfaceStats.ts weighs each texel so); w·Y is Y to the bit where w is 1.
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
      float w = texelFetch(uMask, ivec2(i, j), 0).r;
      if (!(w > 0.0)) continue;
      float y = dot(texelFetch(uSource, ivec2(i, j), 0).rgb, uLuminance);
      s.xy += vec2(y * w, w);
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
