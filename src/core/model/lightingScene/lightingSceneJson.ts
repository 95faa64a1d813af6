/**
 * A lighting scene as the file it is written to (docs/scene-format.md): versions 1 and 2 exactly as
 * the object (a box room is width, height, depth and six reflectances), version 3 with its room
 * written back as the author's `room` object (outline, height, slopes, reflectance, openings; the
 * normalised shape and the box record are what a reader derives from it, never written).
 * parseLightingScene(lightingSceneJson(scene)) gives the scene back.
 */
import { roomInputOf } from '../../room/roomInputOf';
import { skyJson, windowJson } from './daylightJson';
import type { LightingScene } from './lightingScene';

export function lightingSceneJson(scene: LightingScene): Record<string, unknown> {
  if (!scene.room.shape && !scene.daylight) return scene as unknown as Record<string, unknown>;
  const { daylight, ...rest } = scene;
  const sky = daylight?.sky ? { sky: skyJson(daylight.sky) } : {};
  const shape = scene.room.shape;
  // A version-2 box with windows has a shape (the reader's, from the windows): it is written as the box and its windows.
  if (!shape || scene.version !== 3) {
    const { shape: _, ...box } = scene.room;
    const windows = daylight && daylight.windows.length > 0 ? { windows: daylight.windows.map(windowJson) } : {};
    return { ...rest, room: box, ...windows, ...sky };
  }
  const { outline, height, slopes, openings, reflectance } = roomInputOf(shape);
  const glazed = openings?.map((o, i) => (daylight?.transmittance[i] !== undefined ? { ...o, transmittance: daylight.transmittance[i] } : o));
  const room = { outline, height, ...(slopes ? { slopes } : {}), reflectance, ...(glazed ? { openings: glazed } : {}) };
  return { ...rest, version: 3, room, ...sky };
}
