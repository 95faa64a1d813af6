import type { BakeScene } from '../bakeScene';
import type { DaylightBakeInput } from './startDaylightBakeJob';
import { daylightWindows } from './daylightWindows';

/** What a daylight bake needs, or null when the scene has no daylight to bake: no `daylight`, no shaped room, no window, or neither sky nor sun. */
export function daylightBakeInput(scene: BakeScene, enclosed: BakeScene): DaylightBakeInput | null {
  const { daylight } = scene;
  const shape = scene.room.shape;
  const enclosure = enclosed.room.enclosure;
  if (!daylight || !shape || !enclosure || (!daylight.sky && !daylight.sun)) return null;
  const windows = daylightWindows(shape, enclosure.offset, daylight.glazing);
  if (windows.length === 0) return null;
  return { enclosed, daylight, windows, needsRays: !shape.convex || (scene.objects?.length ?? 0) > 0 };
}
