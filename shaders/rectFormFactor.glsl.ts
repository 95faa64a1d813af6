/**
 * Form factor from a differential area at p (unit normal n) to a planar
 * rectangle, Lambert's contour integral (Howell's catalogue, case B-1; Cohen &
 * Wallace, "Radiosity and Realistic Image Synthesis" §4.4):
 * F = (1/2π) Σ γ_i · n·(r_i × r_{i+1})/|r_i × r_{i+1}|, γ_i the angle between
 * successive vertex vectors, here as atan(|a×b|, a·b), which stays accurate for
 * small, distant polygons where acos of a dot product near 1 would not. The
 * rectangle must lie wholly in front of p (as every other wall of a convex box
 * lies in front of a wall's receiving point); where it may not (object
 * receivers), brightPatchGather.glsl.ts clips it first. Self-contained: every
 * input is a function argument.
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
