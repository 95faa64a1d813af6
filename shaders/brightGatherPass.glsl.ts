/**
 * Illuminance at each texel centre of one receiving room surface from the bright patches, in the
 * empty room (src/engines/bake/runBrightPatchPass.ts, docs/baker.md "Stiff scenes: bright
 * patches"): the loop and its form factors are brightPatchGather.glsl.ts's, without occlusion.
 * Patches on the receiving surface itself are skipped (a plane does not see itself). Scene data
 * come in as uniforms and the patch table, so the program compiles once per context.
 */
import { brightPatchGather } from './brightPatchGather.glsl';
import { fragmentPass } from './fragmentPass.glsl';

export const brightGatherPass = fragmentPass(
  {
    uPatches: 'sampler2D',
    uPatchCount: 'int',
    uOrigin: 'vec3',
    uAxisU: 'vec3',
    uAxisV: 'vec3',
    uNormal: 'vec3',
    uResolution: 'vec2',
    uSurface: 'int',
  },
  /* glsl */ `${brightPatchGather(null)}out vec4 outColor;
void main() {
  vec2 uv = gl_FragCoord.xy / uResolution;
  vec3 p = uOrigin + uAxisU * uv.x + uAxisV * uv.y;
  outColor = vec4(brightPatchIrradiance(uPatches, uPatchCount, uSurface, p, uNormal), 1.0);
}
`,
);
