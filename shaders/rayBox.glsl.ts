/**
 * Analytic ray–box exit for a ray starting inside (or on) the box [0, room]:
 * the slab method (Kay & Kajiya 1986) reduced to the far planes, which is all
 * a ray leaving an interior point can hit. Returns the exit distance and the
 * axis hit; the sign of the direction on that axis says which of the two
 * walls. Self-contained: the box comes in as an argument.
 */
export const rayBox = /* glsl */ `
float rayExit(vec3 origin, vec3 dir, vec3 room, out int axis) {
  vec3 safeDir = sign(dir) * max(abs(dir), vec3(1e-12));
  safeDir = mix(safeDir, vec3(1e-12), equal(dir, vec3(0.0)));
  vec3 inv = 1.0 / safeDir;
  vec3 tFar = max(-origin * inv, (room - origin) * inv);
  axis = tFar.x < tFar.y ? (tFar.x < tFar.z ? 0 : 2) : (tFar.y < tFar.z ? 1 : 2);
  return min(tFar.x, min(tFar.y, tFar.z));
}
`;
