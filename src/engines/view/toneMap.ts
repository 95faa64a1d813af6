import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { IDENTITY3 } from './cat16';
import { mulVec3, type Mat3 } from './colourMatrices';

/** TypeScript mirror of toneMap.glsl.ts (same constants, same order): for tests, legends and CPU previews. */

const clamp01 = (x: number) => Math.min(1, Math.max(0, x));
const luminanceOf = (c: Rgb) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
/** Column-major 3×3 times a vector, as GLSL's mat3(…) * v. */
const mulColumnMajor = (m: readonly number[], v: Rgb): Rgb => [m[0] * v[0] + m[3] * v[1] + m[6] * v[2], m[1] * v[0] + m[4] * v[1] + m[7] * v[2], m[2] * v[0] + m[5] * v[1] + m[8] * v[2]];

/** Hue-preserving gamut mapping: a negative component is lifted to 0 by mixing with the grey of the same luminance (toneMap.glsl.ts). */
export function gamutMap(c: Rgb): Rgb {
  const y = luminanceOf(c);
  if (!(y > 0)) return [0, 0, 0];
  const m = Math.min(c[0], c[1], c[2]);
  if (m >= 0) return c;
  const t = y / (y - m);
  return [y + t * (c[0] - y), y + t * (c[1] - y), y + t * (c[2] - y)];
}

// AgX (Troy Sobotka; the minimal fit of Filament / three.js AgXToneMapping, Rec. 2020 working space), column-major as the GLSL.
const SRGB_TO_REC2020 = [0.6274, 0.0691, 0.0164, 0.3293, 0.9195, 0.088, 0.0433, 0.0113, 0.8956];
const REC2020_TO_SRGB = [1.6605, -0.1246, -0.0182, -0.5876, 1.1329, -0.1006, -0.0728, -0.0083, 1.1187];
const AGX_INSET = [0.856627153315983, 0.137318972929847, 0.11189821299995, 0.0951212405381588, 0.761241990602591, 0.0767994186031903, 0.0482516061458583, 0.101439036467562, 0.811302368396859];
const AGX_OUTSET = [1.1271005818144368, -0.1413297634984383, -0.14132976349843826, -0.11060664309660323, 1.157823702216272, -0.11060664309660294, -0.016493938717834573, -0.016493938717834257, 1.2519364065950405];
/** log2 of the darkest and brightest values AgX encodes: 0.18 · 2^−10 and 0.18 · 2^6.5. */
const AGX_MIN_EV = -12.47393;
const AGX_MAX_EV = 4.026069;
const agxContrast = (x: number) => {
  const x2 = x * x;
  const x4 = x2 * x2;
  return 15.5 * x4 * x2 - 40.14 * x4 * x + 31.96 * x4 - 6.868 * x2 * x + 0.4298 * x2 + 0.1191 * x - 0.00232;
};

/** AgX per channel of a linear colour already multiplied by the exposure (three.js AgXToneMapping, no look); linear sRGB in 0..1. The display applies its curve to the largest component (agxMaxRgb). */
export function agx(color: Rgb): Rgb {
  let c = mulColumnMajor(AGX_INSET, mulColumnMajor(SRGB_TO_REC2020, color));
  c = c.map((v) => agxContrast(clamp01((Math.log2(Math.max(v, 1e-10)) - AGX_MIN_EV) / (AGX_MAX_EV - AGX_MIN_EV)))) as Rgb;
  c = mulColumnMajor(AGX_OUTSET, c).map((v) => Math.pow(Math.max(0, v), 2.2)) as Rgb;
  return mulColumnMajor(REC2020_TO_SRGB, c).map(clamp01) as Rgb;
}

/**
 * The AgX curve applied to the largest component, the colour scaled with it (ratios kept): a grey
 * gets exactly AgX's grey, a colour keeps its chromaticity (hue and saturation) at every level,
 * so a gel stays its colour however bright (toneMap.glsl.ts).
 */
export function agxMaxRgb(color: Rgb): Rgb {
  const peak = Math.max(color[0], color[1], color[2]);
  if (!(peak > 0)) return [0, 0, 0];
  const k = agx([peak, peak, peak])[1] / peak;
  return [color[0] * k, color[1] * k, color[2] * k];
}

/** sRGB OETF (IEC 61966-2-1). */
export function linearToSrgb(c: number): number {
  const x = clamp01(c);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055;
}

/** The linear colour before the tone curve: luminance × exposure, adapted (row-major 3×3), gamut-mapped. */
export function adaptedLinear(luminance: Rgb, exposure: number, adapt: Mat3 = IDENTITY3): Rgb {
  return gamutMap(mulVec3(adapt, [luminance[0] * exposure, luminance[1] * exposure, luminance[2] * exposure]));
}

/** Luminance (cd/m², RGB) to display sRGB in 0..1, as the viewer's shader does (`adapt`: the chromatic adaptation, identity by default). */
export function displayColor(luminance: Rgb, exposure: number, adapt: Mat3 = IDENTITY3): Rgb {
  return agxMaxRgb(adaptedLinear(luminance, exposure, adapt)).map(linearToSrgb) as Rgb;
}
