/**
 * Fixed passes of the "bright patch" first bounce (src/engines/bake/brightPatches.ts,
 * docs/baker.md "Bright patches"): tile sums of a direct map, the residual map
 * the Monte Carlo gather reads, and the deterministic gather from the bright
 * patches with exact point-to-rectangle form factors. Scene data come in as
 * uniforms and a small data texture, so each program compiles once per context.
 */
import { fragmentHeader } from './fullscreen.glsl';

/**
 * Sums over one tile of uTile × uTile texels of a direct map E (lux, RGB),
 * with exitance M = ρ·E and its photometric value y = Y(M):
 * mode 0 → (Σ E_r·a, Σ E_g·a, Σ E_b·a, Σ y²·a);
 * mode 1 → (Σ y·a·u, Σ y·a·v, Σ y·a·u², Σ y·a·v²), u, v the texel centre
 * relative to the tile's corner, metres (small numbers keep float32 exact enough).
 * Drawn into a viewport of an atlas whose corner is uOffset.
 */
export const tileSumFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uMap;
uniform ivec2 uOffset;
uniform int uTile;
uniform int uMode;
uniform vec2 uTexel;
uniform vec3 uRho;
out vec4 outColor;
void main() {
  ivec2 tile = ivec2(gl_FragCoord.xy) - uOffset;
  ivec2 size = textureSize(uMap, 0);
  float area = uTexel.x * uTexel.y;
  vec4 sum = vec4(0.0);
  for (int j = 0; j < uTile; j++) {
    for (int i = 0; i < uTile; i++) {
      ivec2 q = tile * uTile + ivec2(i, j);
      if (q.x >= size.x || q.y >= size.y) continue;
      vec3 e = texelFetch(uMap, q, 0).rgb;
      float y = dot(vec3(0.2126, 0.7152, 0.0722), uRho * e) * area;
      vec2 uv = (vec2(i, j) + 0.5) * uTexel;
      if (uMode == 0) sum += vec4(e * area, y * y / area);
      else sum += vec4(y * uv, y * uv * uv);
    }
  }
  outColor = sum;
}
`;

/** Direct map with the texels of bright tiles (uMask = 1 per tile) set to zero: what the Monte Carlo gather still samples. */
export const residualFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uMap;
uniform sampler2D uMask;
uniform int uTile;
out vec4 outColor;
void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  float bright = texelFetch(uMask, p / uTile, 0).r;
  outColor = vec4(texelFetch(uMap, p, 0).rgb * (1.0 - bright), 1.0);
}
`;

/**
 * Form factor from a differential area at p (unit normal n) to a planar
 * polygon, Lambert's contour integral (Howell's catalogue, case B-1; Cohen &
 * Wallace, "Radiosity and Realistic Image Synthesis" §4.4):
 * F = (1/2π) Σ γ_i · n·(r_i × r_{i+1})/|r_i × r_{i+1}|, γ_i the angle between
 * successive vertex vectors, here as atan(|a×b|, a·b), which stays accurate for
 * small, distant polygons where acos of a dot product near 1 would not. The
 * rectangle lies on a wall of a convex box, so it is wholly in front of any
 * other wall's receiving point: no clipping, no visibility.
 */
export const rectFormFactor = /* glsl */ `
float contourEdge(vec3 a, vec3 b, vec3 n) {
  vec3 c = cross(a, b);
  float l = length(c);
  return l < 1e-30 ? 0.0 : atan(l, dot(a, b)) * dot(n, c) / l;
}
float rectFormFactor(vec3 p, vec3 n, vec3 centre, vec3 halfU, vec3 halfV) {
  vec3 r0 = centre - halfU - halfV - p;
  vec3 r1 = centre + halfU - halfV - p;
  vec3 r2 = centre + halfU + halfV - p;
  vec3 r3 = centre - halfU + halfV - p;
  float s = contourEdge(r0, r1, n) + contourEdge(r1, r2, n) + contourEdge(r2, r3, n) + contourEdge(r3, r0, n);
  return min(abs(s) * 0.15915494309189535, 1.0);
}
`;

/**
 * Illuminance at each texel centre of one receiving surface from the bright
 * patches: E = Σ_j M_j · F(p → rect_j), exact (contour integral) within 30 half
 * edges of a patch, the point form factor beyond (where it differs from the
 * exact one by about 1e-3 relative: Howell's catalogue, the A₂ ≪ d² limit).
 * uPatches holds 4 texels per patch (row k): (centre.xyz, source surface
 * index), (half edge along u as a world vector, ·), (half edge along v, ·),
 * (exitance M.rgb, ·). Patches on the receiving surface itself are skipped (a
 * plane does not see itself).
 */
export const brightGatherFragment = /* glsl */ `${fragmentHeader}
uniform sampler2D uPatches;
uniform int uPatchCount;
uniform vec3 uOrigin;
uniform vec3 uAxisU;
uniform vec3 uAxisV;
uniform vec3 uNormal;
uniform vec2 uResolution;
uniform int uSurface;
// (distance / largest half edge)² beyond which the point form factor is used.
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
`;
