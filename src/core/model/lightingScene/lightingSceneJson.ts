/**
 * A lighting scene as the file it is written to (docs/scene-format.md): versions 1 and 2 exactly as
 * the object (a box room is width, height, depth and six reflectances), version 3 with its room
 * written back as the author's `room` object (outline, height, slopes, reflectance, openings; the
 * normalised shape and the box record are what a reader derives from it, never written).
 * parseLightingScene(lightingSceneJson(scene)) gives the scene back.
 */
import { roomInputOf } from '../../room/roomInputOf';
import type { LightingScene } from './lightingScene';

export function lightingSceneJson(scene: LightingScene): Record<string, unknown> {
  const shape = scene.room.shape;
  if (!shape) return scene as unknown as Record<string, unknown>;
  const { outline, height, slopes, openings, reflectance } = roomInputOf(shape);
  const room = { outline, height, ...(slopes ? { slopes } : {}), reflectance, ...(openings ? { openings } : {}) };
  return { ...scene, version: 3, room };
}
