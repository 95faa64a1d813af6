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
