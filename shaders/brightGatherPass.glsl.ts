/**
 * Illuminance at each texel centre of one receiving surface from the bright
 * patches (src/engines/bake/runBrightPatchPass.ts, docs/baker.md "Stiff
 * scenes: bright patches"): E = Σ_j M_j · F(p → rect_j), exact (contour
 * integral) within 30 half edges of a patch, the point form factor beyond
 * (where it differs from the exact one by about 1e-3 relative: Howell's
 * catalogue, the A₂ ≪ d² limit). uPatches holds 4 texels per patch (row k,
 * src/engines/bake/patchTable.ts): (centre.xyz, source surface index), (half
 * edge along u as a world vector, ·), (half edge along v, ·), (exitance
 * M.rgb, ·). Patches on the receiving surface itself are skipped (a plane
 * does not see itself). Scene data come in as uniforms and the patch table,
 * so the program compiles once per context.
 */
import { fragmentPass } from './fragmentPass.glsl';
import { rectFormFactor } from './rectFormFactor.glsl';

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
  /* glsl */ `// (distance / largest half edge)² beyond which the point form factor is used.
const float FAR_FIELD2 = 900.0;
${rectFormFactor}
out vec4 outColor;
void main() {
  vec2 uv = gl_FragCoord.xy / uResolution;
  vec3 p = uOrigin + uAxisU * uv.x + uAxisV * uv.y;
  vec3 e = vec3(0.0);
  for (int k = 0; k < uPatchCount; k++) {
    vec4 a = texelFetch(uPatches, ivec2(0, k), 0);
    if (int(a.w + 0.5) == uSurface) continue;
    vec3 hu = texelFetch(uPatches, ivec2(1, k), 0).xyz;
    vec3 hv = texelFetch(uPatches, ivec2(2, k), 0).xyz;
    vec3 m = texelFetch(uPatches, ivec2(3, k), 0).rgb;
    vec3 toPatch = a.xyz - p;
    float d2 = dot(toPatch, toPatch);
    float size2 = max(dot(hu, hu), dot(hv, hv));
    if (d2 > FAR_FIELD2 * size2) {
      // Far from the patch: the point (differential-area) form factor
      // A·cosθ_r·cosθ_e/(π d²), relative error O((size/d)²) ≈ 1e-3 here; the
      // exact contour integral only where it matters (4 atan per patch).
      vec3 ne = cross(hu, hv);
      float area = 4.0 * length(ne);
      float f = area * abs(dot(uNormal, toPatch)) * abs(dot(ne, toPatch)) / (length(ne) * 3.141592653589793 * d2 * d2);
      e += m * min(f, 1.0);
    } else {
      e += m * rectFormFactor(p, uNormal, a.xyz, hu, hv);
    }
  }
  outColor = vec4(e, 1.0);
}
`,
);
