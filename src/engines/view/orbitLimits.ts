import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { CameraPresetName } from './cameraPresets';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { clampInsideRoom, EYE_MARGIN } from './frameTheLight';

/** How far the orbit may take a preset's camera (three.js OrbitControls' limits, plus a clamp for the eye camera). */
export interface OrbitLimits {
  minPolarAngle: number;
  maxPolarAngle: number;
  minDistance: number;
  maxDistance: number;
  /** The eye camera's clamp: a position (or orbit target) kept EYE_MARGIN inside the room; absent for the views from outside. */
  inside?: (p: Vec3) => Vec3;
}

/**
 * The orbit limits of a preset in a W×H×D room (or a room of any shape: clampInsideRoom keeps the eye inside its outline). The eye camera is a person in the room: camera and
 * target stay EYE_MARGIN inside the walls, floor and ceiling, and it cannot back away further than
 * the room's diagonal. The top and corner views look into the room from outside: they stay above
 * the floor's plane (polar angle below 90°, so the floor never hides the room) and within three
 * room diagonals of their target.
 */
export function orbitLimits(preset: CameraPresetName, room: { width: number; height: number; depth: number; shape?: ShapedRoom }): OrbitLimits {
  const diagonal = Math.hypot(room.width, room.height, room.depth);
  if (preset === 'eye') {
    return { minPolarAngle: 0, maxPolarAngle: Math.PI, minDistance: 0.1, maxDistance: diagonal, inside: (p) => clampInsideRoom(p, room, EYE_MARGIN) };
  }
  return { minPolarAngle: 0, maxPolarAngle: Math.PI / 2 - 0.02, minDistance: 0.5, maxDistance: 3 * diagonal + (preset === 'top' ? 4 * Math.max(room.width, room.depth) : 0) };
}
