import type { TiltTable } from './types';

/**
 * The TILT multiplying factor for a lamp tilt angle (degrees), linearly
 * interpolated in the file's table and held constant beyond its ends
 * (LM-63-2002 §5.11: "multiplying factors … for the corresponding tilt angles").
 */
export function tiltFactorAt(tilt: TiltTable, angleDeg: number): number {
  const { angles, factors } = tilt;
  if (angleDeg <= angles[0]) return factors[0];
  const n = angles.length;
  if (angleDeg >= angles[n - 1]) return factors[n - 1];
  let i = 0;
  while (angles[i + 1] < angleDeg) i++;
  const t = (angleDeg - angles[i]) / (angles[i + 1] - angles[i]);
  return factors[i] * (1 - t) + factors[i + 1] * t;
}

/**
 * Multiplier on the tabulated candela grid for a luminaire aimed `pitchDeg`
 * away from straight down (docs/scene-format.md orientation: yaw and roll turn about
 * vertical axes, so only the pitch tilts the lamp; the tilt angle is the angle
 * between the luminaire's nadir and the world's down direction).
 *
 * The parser already applied the factor for tilt 0 to the grid (LM-63-2002
 * §5.11: the candela values hold for the luminaire in its test orientation),
 * so another tilt scales by factor(tilt) / factor(0). The lamp-to-luminaire
 * geometry code (1–3) is not used: it tells how the lamp sits in the housing,
 * and the tilt angle from the nadir is what the table is indexed by for all
 * three. Returns 1 for files without TILT data.
 */
export function tiltMultiplier(ph: { tilt?: TiltTable | null }, pitchDeg: number): number {
  if (!ph.tilt) return 1;
  const tiltDeg = (Math.acos(Math.max(-1, Math.min(1, Math.cos((pitchDeg * Math.PI) / 180)))) * 180) / Math.PI;
  const atTest = tiltFactorAt(ph.tilt, 0);
  if (!(atTest > 0)) return 0;
  const m = tiltFactorAt(ph.tilt, tiltDeg) / atTest;
  return Number.isFinite(m) && m > 0 ? m : 0;
}
