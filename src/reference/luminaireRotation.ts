import type { Vec3 } from '../core/model/lightingScene/lightingScene';

/** Row-major 3×3 matrix. */
export type Mat3 = [number, number, number, number, number, number, number, number, number];

const DEG = Math.PI / 180;

// Right-handed rotations by t about the y and x axes (docs/scene-format.md: Ry is
// counterclockwise seen from above, Rx(+90°) turns −y into −z). Written here on
// purpose instead of reusing the baker's or three.js's, so that a sign error in
// either shows up as a disagreement with this reference.
function rotY(t: number): Mat3 {
  const c = Math.cos(t * DEG);
  const s = Math.sin(t * DEG);
  return [c, 0, s, 0, 1, 0, -s, 0, c];
}

function rotX(t: number): Mat3 {
  const c = Math.cos(t * DEG);
  const s = Math.sin(t * DEG);
  return [1, 0, 0, 0, c, -s, 0, s, c];
}

export function multiply(a: Mat3, b: Mat3): Mat3 {
  const m = new Array<number>(9).fill(0) as Mat3;
  for (let r = 0; r < 3; r++) {
    for (let c = 0; c < 3; c++) {
      m[r * 3 + c] = a[r * 3] * b[c] + a[r * 3 + 1] * b[3 + c] + a[r * 3 + 2] * b[6 + c];
    }
  }
  return m;
}

export function transpose(m: Mat3): Mat3 {
  return [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]];
}

export function apply(m: Mat3, v: Vec3): Vec3 {
  return [m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2], m[6] * v[0] + m[7] * v[1] + m[8] * v[2]];
}

/** local → world: Ry(yaw) · Rx(pitch) · Ry(roll) (docs/scene-format.md "Units and frames"). */
export function luminaireToWorld(yaw: number, pitch: number, roll: number): Mat3 {
  return multiply(rotY(yaw), multiply(rotX(pitch), rotY(roll)));
}

/** world → local: the transpose of the orthonormal local → world matrix. */
export function worldToLuminaire(yaw: number, pitch: number, roll: number): Mat3 {
  return transpose(luminaireToWorld(yaw, pitch, roll));
}

/**
 * Photometric angles (IES type C) of a direction given in the luminaire's local
 * frame: γ from the nadir (local −y), C from local +x toward local −z, in [0, 360).
 * Returns null for the zero vector.
 */
export function photometricAngles(local: Vec3): { gammaDeg: number; cDeg: number } | null {
  const len = Math.hypot(local[0], local[1], local[2]);
  if (!(len > 0)) return null;
  const horizontal = Math.hypot(local[0], local[2]);
  // atan2 instead of acos keeps full precision near the nadir and zenith.
  const gammaDeg = Math.atan2(horizontal, -local[1]) / DEG;
  let cDeg = Math.atan2(-local[2], local[0]) / DEG;
  if (cDeg < 0) cDeg += 360;
  if (cDeg >= 360) cDeg -= 360;
  return { gammaDeg, cDeg };
}
