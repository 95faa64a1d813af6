import type { Rgb } from '../../core/model/lightingScene/lightingScene';

/**
 * Largest reflectance an imported colour becomes. Exporters write white as Kd 1 or base colour 1,
 * which no real surface reaches (white emulsion is 0.75–0.9, IES Lighting Handbook 10th ed., as
 * src/core/catalog/surface-finishes.json cites); the contract needs ρ < 1 (at 1 a closed room
 * would never lose light).
 */
export const MAX_REFLECTANCE = 0.95;

/** Each component clamped to [0, MAX_REFLECTANCE]; a warning (prefixed by `what`) when anything changed. */
export function clampReflectance(rgb: Rgb, what: string, warnings: string[]): Rgb {
  const out = rgb.map((x) => Math.min(MAX_REFLECTANCE, Math.max(0, x))) as Rgb;
  if (out.some((x, i) => x !== rgb[i])) {
    warnings.push(`${what} [${rgb.map((x) => round(x)).join(', ')}] clamped to [0, ${MAX_REFLECTANCE}] → [${out.map((x) => round(x)).join(', ')}]`);
  }
  return out;
}

function round(x: number): number {
  return Math.round(x * 1000) / 1000;
}
