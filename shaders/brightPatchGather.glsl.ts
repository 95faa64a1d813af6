/**
 * The bright-patch loop (docs/baker.md, "Stiff scenes: bright patches"), one chunk for both bright
 * gather passes: `vec3 brightPatchIrradiance(patches, patchCount, receiver, p, n)` is the
 * illuminance at the point p (unit normal n) from every patch of the table that does not lie on
 * surface `receiver`: E = Σ_j M_j · F(p → rect_j), exact (Lambert's contour integral,
 * rectFormFactor.glsl.ts) within 30 half edges of a patch, the point form factor beyond (where it
 * differs from the exact one by about 1e-3 relative: Howell's catalogue, the A₂ ≪ d² limit).
 * `patches` holds 4 texels per patch (row k, src/engines/bake/patchTable.ts): (centre.xyz, source
 * surface index), (half edge along u as a world vector, ·), (half edge along v, ·), (exitance
 * M.rgb, ·). A row with surface index −1 ends the table early (selectBrightPatchesOnGpu.ts).
 *
 * The receiver cosine. E = ∫ L cos θ dω is taken over the hemisphere in front of the receiver:
 * light arriving from behind a surface does not light its front, so the geometry term is
 * max(cos θ_r, 0) — the same clamp the contour integral gets by clipping the rectangle to the
 * half-space in front of p. A room surface of the empty box never sees a patch behind it (every
 * other wall of a convex box lies wholly in front), so there max and |cos| agree to the bit and the
 * unclipped contour integral is exact. An object texel (the atlas) can face away from a patch
 * (the underside of a shelf, a seat's back turned to a lit wall), and |cos θ_r| would light its
 * front with the light that falls on its back — and make the far field disagree with the clipped
 * near field at the 30-half-edge switch. The emitter cosine is |cos θ_e|: the patch's normal
 * cross(hu, hv) points into or out of the room depending on the wall's axes, and a patch on a
 * wall emits only into the room, where every receiver lies.
 *
 * `objects` (a scene with objects, null for the empty room): each patch's contribution is
 * multiplied by the visibility of its centre from p (one shadow ray through the objects' BVH,
 * objectTracing.glsl.ts; exact where the whole patch is seen or hidden, all-or-nothing for a patch
 * partly hidden, the error confined to the penumbra band of an occluder edge), and the rectangle
 * is clipped to the receiver's front half-space (Sutherland–Hodgman against one plane) before the
 * contour integral, because the receivers then include object texels that may see a patch
 * straddle their horizon. For wall receivers the clip never cuts.
 */
import { objectTracing } from './objectTracing.glsl';
import { rectFormFactor } from './rectFormFactor.glsl';

/** The objects' BVH the shadow rays go through (its texture width), or null: the empty room. */
export interface BrightPatchOcclusion {
  bvhWidth: number;
  /**
   * Patches on the objects' atlas charts too (source index ≥ ATLAS_SOURCE = 6, a shaped room's
   * surfaces and its furniture): such a patch emits only on its front side (cross(hu, hv) is the
   * chart's front normal, src/engines/bake/tileFrame.ts), where a wall's patch in the box emits
   * into the whole box.
   */
  charts?: boolean;
}

/** Form factor dA(p, n) → rectangle, the rectangle clipped to the half-space in front of p (needs rectFormFactor's contourEdge). */
const clippedRectFormFactor = /* glsl */ `// Form factor dA(p, n) → rectangle, the rectangle clipped to the half-space in front of p.
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
`;

/** A chart's patch lights only what lies in front of it (a wall of a shaped room has the outside behind it, a table top the floor under it). */
const oneSidedCharts = /* glsl */ `    if (a.w > 5.5 && dot(cross(hu, hv), a.xyz - p) >= 0.0) continue;
`;

/** The GLSL of `brightPatchIrradiance` and what it needs; the BVH samplers are objectTracing's (uBvhNodes, uBvhTriangles). */
export function brightPatchGather(objects: BrightPatchOcclusion | null): string {
  const nearField = objects ? 'clippedRectFormFactor' : 'rectFormFactor';
  const add = objects ? 'if (f > 0.0) e += m * f * visibility(p, n, a.xyz);' : 'e += m * f;';
  return /* glsl */ `// (distance / largest half edge)² beyond which the point form factor is used.
const float FAR_FIELD2 = 900.0;
${rectFormFactor}
${objects ? `${objectTracing(objects.bvhWidth)}${clippedRectFormFactor}` : ''}vec3 brightPatchIrradiance(sampler2D patches, int patchCount, int receiver, vec3 p, vec3 n) {
  vec3 e = vec3(0.0);
  for (int k = 0; k < patchCount; k++) {
    vec4 a = texelFetch(patches, ivec2(0, k), 0);
    // Surface index −1: the end of a table chosen on the GPU (its length is not known on the CPU).
    if (a.w < -0.5) break;
    if (int(a.w + 0.5) == receiver) continue;
    vec3 hu = texelFetch(patches, ivec2(1, k), 0).xyz;
    vec3 hv = texelFetch(patches, ivec2(2, k), 0).xyz;
${objects?.charts ? oneSidedCharts : ''}    vec3 m = texelFetch(patches, ivec2(3, k), 0).rgb;
    vec3 toPatch = a.xyz - p;
    float d2 = dot(toPatch, toPatch);
    float size2 = max(dot(hu, hu), dot(hv, hv));
    float f;
    if (d2 > FAR_FIELD2 * size2) {
      // Far from the patch: the point (differential-area) form factor A·cosθ_r·cosθ_e/(π d²),
      // relative error O((size/d)²) ≈ 1e-3 here; the exact contour integral only where it matters
      // (4 atan per patch). cosθ_r clamped at 0: light from behind does not reach the front.
      vec3 ne = cross(hu, hv);
      float area = 4.0 * length(ne);
      f = min(area * max(dot(n, toPatch), 0.0) * abs(dot(ne, toPatch)) / (length(ne) * 3.141592653589793 * d2 * d2), 1.0);
    } else {
      f = ${nearField}(p, n, a.xyz, hu, hv);
    }
    ${add}
  }
  return e;
}
`;
}
