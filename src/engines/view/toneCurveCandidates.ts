import type { Rgb } from '../../core/model/lightingScene/lightingScene';

/**
 * The tone curves the viewer's AgX (toneMap.ts) was measured against (docs/viewer.md, "Choosing
 * the tone curve"; scripts/measureToneCurves.ts). Both take a linear sRGB colour already
 * multiplied by the exposure and return linear sRGB in 0..1.
 */

const clamp01 = (x: number) => Math.min(1, Math.max(0, x));
/** Column-major 3×3 times a vector, as GLSL's mat3(…) * v. */
const mulColumnMajor = (m: readonly number[], v: Rgb): Rgb => [m[0] * v[0] + m[3] * v[1] + m[6] * v[2], m[1] * v[0] + m[4] * v[1] + m[7] * v[2], m[2] * v[0] + m[5] * v[1] + m[8] * v[2]];

const ACES_IN = [0.59719, 0.076, 0.0284, 0.35458, 0.90834, 0.13383, 0.04823, 0.01566, 0.83777];
const ACES_OUT = [1.60475, -0.10208, -0.00327, -0.53108, 1.10813, -0.07276, -0.07367, -0.00605, 1.07602];
const rrtOdtFit = (v: number) => (v * (v + 0.0245786) - 0.000090537) / (v * (0.983729 * v + 0.432951) + 0.238081);

/** ACES filmic: Stephen Hill's RRT+ODT fit with three.js's 1/0.6 pre-scale (ACESFilmicToneMapping), the viewer's curve before issue 26. */
export function acesFilmic(color: Rgb): Rgb {
  const a = mulColumnMajor(ACES_IN, [color[0] / 0.6, color[1] / 0.6, color[2] / 0.6]).map(rrtOdtFit) as Rgb;
  return mulColumnMajor(ACES_OUT, a).map(clamp01) as Rgb;
}

/** Khronos PBR Neutral (Khronos Group, "PBR Neutral Specification", 2024; the constants of three.js NeutralToneMapping). */
export function pbrNeutral(color: Rgb): Rgb {
  const startCompression = 0.8 - 0.04;
  const desaturation = 0.15;
  const x = Math.min(color[0], color[1], color[2]);
  const offset = x < 0.08 ? x - 6.25 * x * x : 0.04;
  let c = color.map((v) => v - offset) as Rgb;
  const peak = Math.max(c[0], c[1], c[2]);
  if (peak < startCompression) return c;
  const d = 1 - startCompression;
  const newPeak = 1 - (d * d) / (peak + d - startCompression);
  c = c.map((v) => (v * newPeak) / peak) as Rgb;
  const g = 1 - 1 / (desaturation * (peak - newPeak) + 1);
  return c.map((v) => clamp01(v + (newPeak - v) * g)) as Rgb;
}
