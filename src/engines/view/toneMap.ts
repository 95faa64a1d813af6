import type { Rgb } from '../../core/model/lightingScene';

/** TypeScript mirror of toneMap.glsl.ts (same constants): for tests, legends and CPU previews. */
const IN = [0.59719, 0.07600, 0.02840, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777];
const OUT = [1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602];

function mulColumnMajor(m: number[], v: Rgb): Rgb {
  return [m[0] * v[0] + m[3] * v[1] + m[6] * v[2], m[1] * v[0] + m[4] * v[1] + m[7] * v[2], m[2] * v[0] + m[5] * v[1] + m[8] * v[2]];
}

const fit = (v: number) => (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.432951) + 0.238081);
const clamp01 = (x: number) => Math.min(1, Math.max(0, x));

/** ACES filmic (Hill's fit, as three.js) of a linear colour already multiplied by the exposure. */
export function acesFilmic(color: Rgb): Rgb {
  const a = mulColumnMajor(IN, [color[0] / 0.6, color[1] / 0.6, color[2] / 0.6]).map(fit) as Rgb;
  return mulColumnMajor(OUT, a).map(clamp01) as Rgb;
}

/** sRGB OETF (IEC 61966-2-1). */
export function linearToSrgb(c: number): number {
  const x = clamp01(c);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * Math.pow(x, 1 / 2.4) - 0.055;
}

/** Luminance (cd/m², RGB) to display sRGB in 0..1, as the viewer's shader does. */
export function displayColor(luminance: Rgb, exposure: number): Rgb {
  return acesFilmic([luminance[0] * exposure, luminance[1] * exposure, luminance[2] * exposure]).map(linearToSrgb) as Rgb;
}
