/**
 * Linear sRGB ↔ CIE 1931 XYZ (IEC 61966-2-1, D65 white): XYZ_TO_SRGB is the matrix
 * cctToLinearRgb and xyzToLinearSrgb use (src/core/photometry/cct.ts), SRGB_TO_XYZ its exact
 * inverse, so light colours the engine computed go back to the same XYZ. Row-major 3×3 helpers.
 */
export type Mat3 = readonly [number, number, number, number, number, number, number, number, number];
export type Vec3 = readonly [number, number, number];

export const XYZ_TO_SRGB: Mat3 = [3.2406, -1.5372, -0.4986, -0.9689, 1.8758, 0.0415, 0.0557, -0.204, 1.057];

export function mul3(a: Mat3, b: Mat3): Mat3 {
  const m = new Array<number>(9);
  for (let r = 0; r < 3; r++) for (let c = 0; c < 3; c++) m[3 * r + c] = a[3 * r] * b[c] + a[3 * r + 1] * b[3 + c] + a[3 * r + 2] * b[6 + c];
  return m as unknown as Mat3;
}

export function mulVec3(m: Mat3, v: Vec3): [number, number, number] {
  return [m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2], m[6] * v[0] + m[7] * v[1] + m[8] * v[2]];
}

/** Inverse of a 3×3 by cofactors (the callers' matrices are far from singular). */
export function invert3(m: Mat3): Mat3 {
  const [a, b, c, d, e, f, g, h, i] = m;
  const A = e * i - f * h;
  const B = -(d * i - f * g);
  const C = d * h - e * g;
  const det = a * A + b * B + c * C;
  return [A / det, -(b * i - c * h) / det, (b * f - c * e) / det, B / det, (a * i - c * g) / det, -(a * f - c * d) / det, C / det, -(a * h - b * g) / det, (a * e - b * d) / det];
}

export const SRGB_TO_XYZ: Mat3 = invert3(XYZ_TO_SRGB);
