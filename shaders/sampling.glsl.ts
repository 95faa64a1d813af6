/**
 * Deterministic sample streams for the indirect pass. Per texel, a hashed
 * Cranley–Patterson rotation of the R2 low-discrepancy sequence (Roberts 2018,
 * "The unreasonable effectiveness of quasirandom sequences"), kept in 32-bit
 * fixed point so sample k is exact for any k. Hash: lowbias32 (C. Wellons,
 * "Prospecting for hash functions", 2018).
 */
export const sampling = /* glsl */ `
uint hash32(uint x) {
  x ^= x >> 16; x *= 0x7feb352du;
  x ^= x >> 15; x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

// alpha = (1/g, 1/g^2), g the plastic number, times 2^32.
vec2 r2Sample(uint k, uvec2 rotation) {
  uvec2 q = uvec2(k * 3242174889u, k * 2447445413u) + rotation;
  return vec2(q >> 8u) * (1.0 / 16777216.0);
}

// Cosine-weighted direction about n (Malley's method: uniform disk, lifted).
vec3 cosineDirection(vec2 xi, vec3 n, vec3 tangent, vec3 bitangent) {
  float r = sqrt(xi.x);
  float phi = 6.283185307179586 * xi.y;
  float z = sqrt(max(0.0, 1.0 - xi.x));
  return normalize(tangent * (r * cos(phi)) + bitangent * (r * sin(phi)) + n * max(z, 1e-6));
}
`;
