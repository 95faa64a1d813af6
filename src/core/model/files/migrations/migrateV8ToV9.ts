/** Scene file version 8 → 9 (what version 9 added; docs/model.md). */
import { needsVersion } from '../sceneFileError';
import { sceneDataHasRoomShape } from '../../configuration/roomShapeSupport';

/**
 * 8 → 9: version 9 lets a room have a shape (`room.shape`, issue 29); a version 8 room is the box
 * it always was, which version 9 writes as a room without a shape, so the content reads as is.
 * (An older file with a shape is refused before any step, refuseV9Fields.)
 */
export const migrateV8ToV9 = (doc: Record<string, unknown>): Record<string, unknown> => ({ ...doc, version: 9 });

/** A room shape came with version 9: an older file that has one was not written by luxbox. */
export function refuseV9Fields(doc: Record<string, unknown>, version: number): void {
  if (sceneDataHasRoomShape(doc)) throw needsVersion('configuration.room.shape', 9, version);
}
