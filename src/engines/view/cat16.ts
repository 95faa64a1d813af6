/**
 * CAT16 chromatic adaptation (Li, Li, Wang, Xu, Luo, Cui, Melgosa, Brill, Pointer,
 * "Comprehensive color solutions: CAM16, CAT16, and CAM16-UCS", Color Res. Appl. 42:703–718,
 * 2017): von Kries scaling in the sharpened cone space of M16, one step from the test white to
 * the reference white with the degree of adaptation D,
 *
 *   RGB = M16 · XYZ,  RGB_c = (D · (Y_w / Y_wr) · (RGB_wr / RGB_w) + 1 − D) ⊙ RGB,  XYZ_c = M16⁻¹ · RGB_c,
 *
 * so D = 0 leaves a colour as it is, D = 1 maps the test white exactly to the reference white (at
 * the test white's luminance). The matrix is affine in D: A(D) = D·A(1) + (1 − D)·I.
 *
 * Degree of adaptation (CIECAM02, CIE 159:2004, kept by CAM16):
 *   D = F · (1 − (1/3.6) · exp((−L_A − 42) / 92)),  F = 1 for an average surround,
 * with L_A the adapting luminance in cd/m².
 */
import { SRGB_TO_XYZ, XYZ_TO_SRGB, invert3, mul3, mulVec3, type Mat3, type Vec3 } from './colourMatrices';

/** M16 (Li et al. 2017), rows: XYZ → sharpened RGB. */
export const M16: Mat3 = [0.401288, 0.650173, -0.051461, -0.250268, 1.204414, 0.045854, -0.002079, 0.048952, 0.953127];
/** Its inverse. */
export const M16_INV: Mat3 = invert3(M16);

/** Surround factor F of an average surround (CIECAM02 / CAM16). */
export const F_AVERAGE = 1;

/** The identity, row-major. */
export const IDENTITY3: Mat3 = [1, 0, 0, 0, 1, 0, 0, 0, 1];

/** CIECAM02 / CAM16 degree of adaptation at adapting luminance `la` (cd/m²), clamped to 0..1; a bad L_A counts as 0 cd/m². */
export function degreeOfAdaptation(la: number, f: number = F_AVERAGE): number {
  const l = Number.isFinite(la) && la > 0 ? la : 0;
  const d = f * (1 - (1 / 3.6) * Math.exp((-l - 42) / 92));
  return Math.min(1, Math.max(0, d));
}

/**
 * The one-step CAT16 from `white` (XYZ of the test white) to `reference` (XYZ of the reference
 * white) at degree D, as a row-major 3×3 on XYZ. A white with a non-positive or non-finite
 * sharpened component (not a light colour) gives the identity.
 */
export function cat16Xyz(white: Vec3, reference: Vec3, d: number): Mat3 {
  const w = mulVec3(M16, white);
  const wr = mulVec3(M16, reference);
  const dd = Math.min(1, Math.max(0, Number.isFinite(d) ? d : 0));
  const ratio = white[1] / reference[1];
  const scale = [0, 1, 2].map((i) => dd * ratio * (wr[i] / w[i]) + 1 - dd);
  if (!(white[1] > 0) || !(reference[1] > 0) || w.some((v) => !(v > 0)) || wr.some((v) => !(v > 0)) || scale.some((s) => !Number.isFinite(s))) return IDENTITY3;
  const diag: Mat3 = [scale[0], 0, 0, 0, scale[1], 0, 0, 0, scale[2]];
  return mul3(M16_INV, mul3(diag, M16));
}

/** CAT16 on linear sRGB (IEC 61966-2-1 primaries) from the light `whiteRgb` to the display white (RGB 1, 1, 1 = D65) at degree D. */
export function cat16LinearSrgb(whiteRgb: Vec3, d: number): Mat3 {
  const white = mulVec3(SRGB_TO_XYZ, whiteRgb);
  const reference = mulVec3(SRGB_TO_XYZ, [1, 1, 1]);
  return mul3(XYZ_TO_SRGB, mul3(cat16Xyz(white, reference, d), SRGB_TO_XYZ));
}
