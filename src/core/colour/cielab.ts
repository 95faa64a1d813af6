/**
 * CIE 1976 L*a*b* (CIE 15:2004, §8.2.1) and its hue angle h_ab, for measuring how the display
 * keeps a colour's hue (docs/viewer.md, "Choosing the tone curve"). White: the display's D65 by
 * default, as linear sRGB (1, 1, 1) through the IEC 61966-2-1 matrix.
 */
const SRGB_TO_XYZ_ROWS = [0.4124, 0.3576, 0.1805, 0.2126, 0.7152, 0.0722, 0.0193, 0.1192, 0.9505];

/** Linear sRGB → XYZ (IEC 61966-2-1). */
export function linearSrgbToXyz(c: readonly [number, number, number]): [number, number, number] {
  const m = SRGB_TO_XYZ_ROWS;
  return [m[0] * c[0] + m[1] * c[1] + m[2] * c[2], m[3] * c[0] + m[4] * c[1] + m[5] * c[2], m[6] * c[0] + m[7] * c[1] + m[8] * c[2]];
}

/** sRGB EOTF (IEC 61966-2-1): display value 0..1 → linear. */
export function srgbToLinear(v: number): number {
  return v <= 0.04045 ? v / 12.92 : Math.pow((v + 0.055) / 1.055, 2.4);
}

/** The display white D65 as XYZ (linear sRGB 1, 1, 1). */
export const D65_XYZ = linearSrgbToXyz([1, 1, 1]);

const f = (t: number) => (t > (6 / 29) ** 3 ? Math.cbrt(t) : t / (3 * (6 / 29) ** 2) + 4 / 29);

/** XYZ → L*a*b* relative to `white` (XYZ). */
export function xyzToLab(xyz: readonly [number, number, number], white: readonly [number, number, number] = D65_XYZ): [number, number, number] {
  const [fx, fy, fz] = [f(xyz[0] / white[0]), f(xyz[1] / white[1]), f(xyz[2] / white[2])];
  return [116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)];
}

/** Hue angle h_ab in degrees, 0..360. */
export function hueAngle(lab: readonly [number, number, number]): number {
  const h = (Math.atan2(lab[2], lab[1]) * 180) / Math.PI;
  return h < 0 ? h + 360 : h;
}

/** Chroma C*_ab. */
export function chroma(lab: readonly [number, number, number]): number {
  return Math.hypot(lab[1], lab[2]);
}

/** The smallest difference of two hue angles, degrees (0..180). */
export function hueDifference(a: number, b: number): number {
  const d = Math.abs(a - b) % 360;
  return d > 180 ? 360 - d : d;
}

/** Hue angle of a chromaticity x, y (at any luminance) against `white`. */
export function hueOfChromaticity(x: number, y: number, white: readonly [number, number, number] = D65_XYZ): number {
  const Y = 0.2;
  return hueAngle(xyzToLab([(x / y) * Y, Y, ((1 - x - y) / y) * Y], white));
}
