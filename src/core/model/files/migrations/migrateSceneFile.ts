import type { Catalog } from '../../catalogSchema/catalogSchema';
import { SCENE_FILE_VERSION } from '../sceneFileSchema';
import { SceneFileError } from '../sceneFileError';
import { migrateV8ToV9, refuseV9Fields } from './migrateV8ToV9';
import { migrateV9ToV10, refuseV10Fields } from './migrateV9ToV10';
import { roomShapeSupport, RoomShapeSupportMissing, type MigrationStep } from '../../configuration/roomShapeSupport';

/** Versions below this read through the lazy chunk's steps (legacyMigrations.ts). */
export const LEGACY_BELOW = 8;

/**
 * Migration hook: migrations[n] turns a version-n document into version n+1.
 * A future version adds its step here and bumps SCENE_FILE_VERSION. The steps from versions
 * before LEGACY_BELOW (files from before trees of rails, rare by now) are in the lazy chunk
 * with rooms of any shape (legacyMigrations.ts, roomShapeSupport.ts), loaded before such a file is read.
 */
export const migrations: Record<number, MigrationStep> = {
  8: migrateV8ToV9,
  9: migrateV9ToV10,
};

export function migrateSceneFile(doc: Record<string, unknown>, catalog: Catalog): Record<string, unknown> {
  let d = doc;
  // A room shape in any older file is refused naming the version the file says (the steps before 8 → 9 do not look at the room).
  if (typeof d.version === 'number' && d.version < 9) refuseV9Fields(d, d.version);
  if (typeof d.version === 'number' && d.version < 10) refuseV10Fields(d, d.version);
  while (typeof d.version === 'number' && d.version < SCENE_FILE_VERSION) {
    if (d.version < LEGACY_BELOW && !roomShapeSupport()) throw new RoomShapeSupportMissing(`configuration version ${d.version}`);
    const step = migrations[d.version] ?? roomShapeSupport()?.legacyMigrations[d.version];
    if (!step) throw new SceneFileError(`scene file version ${d.version} is no longer supported`, { code: 'fileVersionUnsupported', params: { version: d.version } });
    d = step(d, catalog);
  }
  return d;
}
