/** Scene file version 8 → 9 (what version 9 added; docs/model.md). */
import { needsVersion } from '../sceneFileError';

/**
 * 8 → 9: version 9 lets a room have a shape (`room.shape`, issue 29); a version 8 room is the box
 * it always was, which version 9 writes as a room without a shape, so the content reads as is.
 */
export function migrateV8ToV9(doc: Record<string, unknown>): Record<string, unknown> {
  refuseV9Fields(doc, 8);
  return { ...doc, version: 9 };
}

/** A room shape came with version 9: an older file that has one was not written by luxbox. */
export function refuseV9Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const room = typeof c === 'object' && c !== null ? (c as Record<string, unknown>).room : undefined;
  if (typeof room === 'object' && room !== null && 'shape' in room) throw needsVersion('configuration.room.shape', 9, version);
}
