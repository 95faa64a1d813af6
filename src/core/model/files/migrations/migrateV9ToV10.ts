/** Scene file version 9 → 10 (what version 10 added; docs/model.md, docs/daylight.md). */
import { needsVersion } from '../sceneFileError';
import { sceneDataHasDaylight } from '../../configuration/roomShapeSupport';

/**
 * 9 → 10: version 10 adds daylight (`daylight`) and a window's glazing (`transmittance` on an
 * opening of `room.shape`); a version-9 room without them is what version 10 writes for a room
 * never given daylight, so the content reads as is. (An older file with either is refused before
 * any step, refuseV10Fields.)
 */
export const migrateV9ToV10 = (doc: Record<string, unknown>): Record<string, unknown> => ({ ...doc, version: 10 });

/** The first glazed opening's path in parsed scene-file JSON, or null. */
function glazedOpening(doc: Record<string, unknown>): string | null {
  const c = doc.configuration as { room?: { shape?: { openings?: unknown } } } | undefined;
  const openings = c?.room?.shape?.openings;
  if (!Array.isArray(openings)) return null;
  const i = openings.findIndex((o) => typeof o === 'object' && o !== null && 'transmittance' in o);
  return i < 0 ? null : `configuration.room.shape.openings[${i}].transmittance`;
}

/** Daylight and glazing came with version 10: an older file that has either was not written by luxbox. */
export function refuseV10Fields(doc: Record<string, unknown>, version: number): void {
  if (sceneDataHasDaylight(doc)) throw needsVersion('configuration.daylight', 10, version);
  const glazed = glazedOpening(doc);
  if (glazed) throw needsVersion(glazed, 10, version);
}
