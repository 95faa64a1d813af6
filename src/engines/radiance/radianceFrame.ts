import type { Vec3 } from '../../core/model/lightingScene/lightingScene';

/**
 * luxbox's world (y up, docs/scene-format.md "Units and frames") in Radiance's frame (z up):
 * (X, Y, Z) = (x, −z, y). The map is a proper rotation (a quarter turn about +x), so handedness
 * and the sign of every rotation angle are kept: a turn about luxbox's +y is the same turn about
 * Radiance's +Z, a turn about +x the same turn about +X. North (luxbox −z) is Radiance +Y.
 */
export function toRadiance(p: Vec3): Vec3 {
  return [p[0], -p[2], p[1]];
}

/** Shortest decimal that reads back to the same float32-level value: 7 significant digits, no exponent noise. */
export function num(x: number): string {
  if (x === 0 || Object.is(x, -0)) return '0';
  return Number(x.toPrecision(7)).toString();
}

export const vecText = (v: Vec3): string => v.map(num).join(' ');
