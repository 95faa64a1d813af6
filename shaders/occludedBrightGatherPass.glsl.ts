/**
 * The bright-patch gather (brightGatherPass.glsl.ts, docs/baker.md "Stiff scenes: bright
 * patches") in a scene with objects, for a room surface (receiver point and normal from the
 * uniforms' frame, uFromAtlas = 0) or for the objects' atlas (point and normal from the G-buffer
 * textures uPoints / uNormals, uFromAtlas = 1; empty texels stay 0).
 *
 * Two changes from the empty room. (1) Occlusion: each patch's contribution is multiplied by the
 * visibility of the patch centre from the receiver (one shadow ray through the objects' BVH). This
 * is exact where the whole patch is seen or hidden and approximates a patch partly hidden by
 * all-or-nothing; patches are at most a tile (≈ 0.1 m) and the error is confined to the penumbra
 * band of an occluder edge as seen from the patch. (2) An object's texel may face away from a
 * patch or see it straddle its horizon, which no wall point of a convex box does: the rectangle is
 * clipped to the receiver's upper half-space (Sutherland–Hodgman against one plane) before
 * Lambert's contour integral (rectFormFactor.glsl.ts), and the far-field point form factor uses
 * max(cos θ_r, 0). For wall receivers the clip never cuts (every patch lies wholly in front).
 */
import { fragmentPass, type FragmentPass } from './fragmentPass.glsl';
import { objectTracing } from './objectTracing.glsl';
import { rectFormFactor } from './rectFormFactor.glsl';

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

export function occludedBrightGatherPass(bvhWidth: number): FragmentPass<typeof occludedBrightGatherUniforms> {
  return fragmentPass(
    occludedBrightGatherUniforms,
    /* glsl */ `// (distance / largest half edge)² beyond which the point form factor is used.
const float FAR_FIELD2 = 900.0;
${rectFormFactor}
${objectTracing(bvhWidth)}
// Form factor dA(p, n) → rectangle, the rectangle clipped to the half-space in front of p.
float clippedRectFormFactor(vec3 p, vec3 n, vec3 centre, vec3 halfU, vec3 halfV) {
  vec3 v[4] = vec3[4](centre - halfU - halfV - p, centre + halfU - halfV - p, centre + halfU + halfV - p, centre - halfU + halfV - p);
  vec3 poly[5];
  int m = 0;
  for (int i = 0; i < 4; i++) {
    vec3 a = v[i];
    vec3 b = v[(i + 1) % 4];
    float ha = dot(n, a);
    float hb = dot(n, b);
    if (ha > 0.0) poly[m++] = a;
    if ((ha > 0.0) != (hb > 0.0)) poly[m++] = a + (b - a) * (ha / (ha - hb));
  }
  if (m < 3) return 0.0;
  float s = 0.0;
  for (int i = 0; i < m; i++) s += contourEdge(poly[i], poly[(i + 1) % m], n);
  return min(abs(s) * 0.15915494309189535, 1.0);
}
out vec4 outColor;
void main() {
  vec3 p;
  vec3 normal;
  if (uFromAtlas == 1) {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec4 point = texelFetch(uPoints, texel, 0);
    if (point.a <= 0.0) {
      outColor = vec4(0.0, 0.0, 0.0, 1.0);
      return;
    }
    p = point.xyz;
    normal = normalize(texelFetch(uNormals, texel, 0).xyz);
  } else {
    vec2 uv = gl_FragCoord.xy / uResolution;
    p = uOrigin + uAxisU * uv.x + uAxisV * uv.y;
    normal = uNormal;
  }
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
    float f;
    if (d2 > FAR_FIELD2 * size2) {
      vec3 ne = cross(hu, hv);
      float area = 4.0 * length(ne);
      f = min(area * max(dot(normal, toPatch), 0.0) * abs(dot(ne, toPatch)) / (length(ne) * 3.141592653589793 * d2 * d2), 1.0);
    } else {
      f = clippedRectFormFactor(p, normal, a.xyz, hu, hv);
    }
    if (f > 0.0) e += m * f * visibility(p, normal, a.xyz);
  }
  outColor = vec4(e, 1.0);
}
`,
  );
}
