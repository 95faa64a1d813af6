/**
 * out = a·scaleA + b·scaleB (sum of bounce maps, direct + indirect, a copy).
 * Each light map is its own texture and every read is clamped to it, so
 * nothing ever bleeds across a wall corner.
 */
import { fragmentPass } from './fragmentPass.glsl';

export const combinePass = fragmentPass(
  { uA: 'sampler2D', uB: 'sampler2D', uScaleA: 'vec3', uScaleB: 'vec3' },
  /* glsl */ `out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 c = texelFetch(uA, p, 0).rgb * uScaleA + texelFetch(uB, p, 0).rgb * uScaleB;
  outColor = vec4(max(c, vec3(0.0)), 1.0);
}
`,
);
