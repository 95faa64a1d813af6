/**
 * Direct map with the texels of bright tiles (uMask = 1 per tile, the surface's
 * first tile at uMaskOffset) set to zero: what the Monte Carlo gather of bounce 1 still samples
 * (src/engines/bake/runBrightPatchPass.ts).
 */
import { fragmentPass } from './fragmentPass.glsl';

export const residualPass = fragmentPass(
  { uMap: 'sampler2D', uMask: 'sampler2D', uTile: 'int', uMaskOffset: 'ivec2' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float bright = texelFetch(uMask, uMaskOffset + p / uTile, 0).r;
  outColor = vec4(texelFetch(uMap, p, 0).rgb * (1.0 - bright), 1.0);
}
`,
);
