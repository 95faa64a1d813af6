import type { BakeScene } from '../bakeScene';
import type { DaylightBakeInput } from './startDaylightBakeJob';
import { daylightWindows } from './daylightWindows';

/** What a daylight bake needs, or null when the scene has no daylight to bake: no `daylight`, no shaped room, no window, or neither sky nor sun. */
export function daylightBakeInput(scene: BakeScene, enclosed: BakeScene): DaylightBakeInput | null {
  if (!scene.daylight?.sky && !scene.daylight?.sun) return null;
  return daylightWindowsInput(scene, enclosed);
}

/** daylightBakeInput whether or not light comes in (the daylight factor's windows after sunset: another sky is put in). */
export function daylightWindowsInput(scene: BakeScene, enclosed: BakeScene): DaylightBakeInput | null {
  const { daylight } = scene;
  const shape = scene.room.shape;
  const enclosure = enclosed.room.enclosure;
  if (!daylight || !shape || !enclosure) return null;
  const windows = daylightWindows(shape, enclosure.offset, daylight.glazing);
  if (windows.length === 0) return null;
  return { enclosed, daylight, windows, needsRays: !shape.convex || (scene.objects?.length ?? 0) > 0 };
}
