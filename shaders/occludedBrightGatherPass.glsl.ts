/**
 * The bright-patch gather (docs/baker.md "Stiff scenes: bright patches") in a scene with objects,
 * for a room surface (receiver point and normal from the uniforms' frame, uFromAtlas = 0) or for
 * the objects' atlas (point and normal from the G-buffer textures uPoints / uNormals,
 * uFromAtlas = 1; empty texels stay 0). The loop is brightPatchGather.glsl.ts's with occlusion:
 * a shadow ray per patch, and the rectangle clipped to the receiver's front half-space (an object
 * texel may face away from a patch or see it straddle its horizon).
 */
import { brightPatchGather } from './brightPatchGather.glsl';
import { fragmentPass, type FragmentPass } from './fragmentPass.glsl';

export const occludedBrightGatherUniforms = {
  uPatches: 'sampler2D',
  uPatchCount: 'int',
  uOrigin: 'vec3',
  uAxisU: 'vec3',
  uAxisV: 'vec3',
  uNormal: 'vec3',
  uResolution: 'vec2',
  uSurface: 'int',
  uBvhNodes: 'sampler2D',
  uBvhTriangles: 'sampler2D',
  uFromAtlas: 'int',
  uPoints: 'sampler2D',
  uNormals: 'sampler2D',
} as const;

/** An atlas texel's own chart as the receiver: source 6 + chart id = 5 + (chart id + 1). */
const ownChart = `
    receiver = 5 + int(texelFetch(uNormals, texel, 0).a + 0.5);`;

/**
 * `charts`: the patch table holds patches on atlas charts (source ATLAS_SOURCE + chart): an atlas
 * texel skips those of its own chart (normal's a = chart id + 1), as a wall skips its own.
 */
export function occludedBrightGatherPass(bvhWidth: number, charts = false): FragmentPass<typeof occludedBrightGatherUniforms> {
  return fragmentPass(
    occludedBrightGatherUniforms,
    /* glsl */ `${brightPatchGather({ bvhWidth, ...(charts ? { charts } : {}) })}out vec4 outColor;
void main() {
  vec3 p;
  vec3 normal;${charts ? '\n  int receiver = uSurface;' : ''}
  if (uFromAtlas == 1) {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 point = texelFetch(uPoints, texel, 0);
    if (point.a <= 0.0) {
      outColor = vec4(0.0, 0.0, 0.0, 1.0);
      return;
    }
    p = point.xyz;
    normal = normalize(texelFetch(uNormals, texel, 0).xyz);${charts ? ownChart : ''}
  } else {
    vec2 uv = gl_FragCoord.xy / uResolution;
    p = uOrigin + uAxisU * uv.x + uAxisV * uv.y;
    normal = uNormal;
  }
  outColor = vec4(brightPatchIrradiance(uPatches, uPatchCount, ${charts ? 'receiver' : 'uSurface'}, p, normal), 1.0);
}
`,
  );
}
