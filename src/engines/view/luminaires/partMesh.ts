import * as THREE from 'three';
import type { LuminairePart, PartFrame, PartRole } from './luminaireModel';

/** A three.js primitive (centred as three builds it) turned into a part: optionally rotated, then moved. */
export function partFrom(geometry: THREE.BufferGeometry, role: PartRole, frame: PartFrame, place: { at?: [number, number, number]; rotate?: [number, number, number]; scale?: [number, number, number] } = {}, side?: -1 | 1): LuminairePart {
  const m = new THREE.Matrix4().compose(new THREE.Vector3(...(place.at ?? [0, 0, 0])), new THREE.Quaternion().setFromEuler(new THREE.Euler(...(place.rotate ?? [0, 0, 0]))), new THREE.Vector3(...(place.scale ?? [1, 1, 1])));
  geometry.applyMatrix4(m);
  const positions = new Float32Array(geometry.getAttribute('position').array);
  const normals = new Float32Array(geometry.getAttribute('normal').array);
  const index = geometry.getIndex();
  const indices = index ? new Uint32Array(index.array) : Uint32Array.from({ length: positions.length / 3 }, (_, i) => i);
  geometry.dispose();
  return { role, frame, positions, normals, indices, ...(side !== undefined ? { side } : {}) };
}

/** A box of size [x, y, z] whose bottom face sits at `bottom` (its centre above `at`'s x, z). */
export function boxPart(size: [number, number, number], role: PartRole, frame: PartFrame, at: [number, number, number]): LuminairePart {
  return partFrom(new THREE.BoxGeometry(...size), role, frame, { at });
}

/** A vertical cylinder (radius, from y0 to y1) at plan point (x, z). */
export function rodPart(radius: number, y0: number, y1: number, role: PartRole, frame: PartFrame, x = 0, z = 0, segments = 12): LuminairePart {
  return partFrom(new THREE.CylinderGeometry(radius, radius, y1 - y0, segments, 1, false), role, frame, { at: [x, (y0 + y1) / 2, z] });
}

/**
 * The light-emitting face, facing local −y (side −1) or +y (side 1), at height y: an ellipse of the
 * given full axes (x, z) drawn as an n-gon whose area equals the ellipse's exactly (radii × √(2π / (n·sin(2π/n)))),
 * or a rectangle.
 */
export function emitterPart(shape: 'round' | 'rectangular', x: number, z: number, y: number, frame: PartFrame, side: -1 | 1, segments = 32): LuminairePart {
  const turn: [number, number, number] = [side < 0 ? Math.PI / 2 : -Math.PI / 2, 0, 0];
  if (shape === 'rectangular') return partFrom(new THREE.PlaneGeometry(x, z), 'emitter', frame, { at: [0, y, 0], rotate: turn }, side);
  const k = Math.sqrt((2 * Math.PI) / (segments * Math.sin((2 * Math.PI) / segments)));
  // CircleGeometry lies in xy facing +z; scaled to the ellipse, then laid flat facing down (or up).
  const g = new THREE.CircleGeometry(1, segments);
  g.scale((x / 2) * k, (z / 2) * k, 1);
  return partFrom(g, 'emitter', frame, { at: [0, y, 0], rotate: turn }, side);
}
