import { degreesToRadians } from '../../core/degreesToRadians';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';

/** Row-major 3×3 matrix. */
export type Mat3 = [number, number, number, number, number, number, number, number, number];

const DEG = Math.PI / 180;

// Angles reduced before conversion (degreesToRadians): any finite angle turns exactly (issue 32).
function ry(t: number): Mat3 {
  const c = Math.cos(degreesToRadians(t));
  const s = Math.sin(degreesToRadians(t));
  // Right-handed about +y: +x turns toward −z (counterclockwise seen from above).
  return [c, 0, s, 0, 1, 0, -s, 0, c];
}

function rx(t: number): Mat3 {
  const c = Math.cos(degreesToRadians(t));
  const s = Math.sin(degreesToRadians(t));
  // Right-handed about +x: +90° turns −y (the nadir) into −z.
  return [1, 0, 0, 0, c, -s, 0, s, c];
}

export function multiply(a: Mat3, b: Mat3): Mat3 {
  const r = new Array<number>(9).fill(0) as Mat3;
  for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) r[i * 3 + j] = a[i * 3] * b[j] + a[i * 3 + 1] * b[3 + j] + a[i * 3 + 2] * b[6 + j];
  return r;
}

/** world = Ry(yaw) · Rx(pitch) · Ry(roll) · local, angles in degrees (docs/scene-format.md "Units and frames"). */
export function luminaireRotation(yaw: number, pitch: number, roll: number): Mat3 {
  return multiply(ry(yaw), multiply(rx(pitch), ry(roll)));
}

export function applyMat3(m: Mat3, v: Vec3): Vec3 {
  return [m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2], m[6] * v[0] + m[7] * v[1] + m[8] * v[2]];
}

export function transpose(m: Mat3): Mat3 {
  return [m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]];
}

/**
 * Photometric angles of a local direction (γ from the nadir −y, C from +x toward −z, the IES
 * type C frame of src/core/photometry/types.ts): [γ, C] in degrees, C in [0, 360).
 */
export function photometricAngles(local: Vec3): [number, number] {
  const len = Math.hypot(local[0], local[1], local[2]);
  const gamma = Math.acos(Math.min(1, Math.max(-1, -local[1] / len))) / DEG;
  let c = Math.atan2(-local[2], local[0]) / DEG;
  if (c < 0) c += 360;
  return [gamma, c];
}
