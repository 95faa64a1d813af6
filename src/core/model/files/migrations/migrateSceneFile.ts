import type { Catalog } from '../../catalogSchema/catalogSchema';
import { SCENE_FILE_VERSION } from '../sceneFileSchema';
import { SceneFileError } from '../sceneFileError';
import { migrateV1ToV2 } from './migrateV1ToV2';
import { migrateV2ToV3 } from './migrateV2ToV3';
import { migrateV3ToV4 } from './migrateV3ToV4';
import { migrateV4ToV5 } from './migrateV4ToV5';
import { migrateV5ToV6 } from './migrateV5ToV6';
import { migrateV6ToV7 } from './migrateV6ToV7';
import { migrateV7ToV8 } from './migrateV7ToV8';
import { migrateV8ToV9, refuseV9Fields } from './migrateV8ToV9';

/**
 * Migration hook: migrations[n] turns a version-n document into version n+1.
 * A future version adds its step here and bumps SCENE_FILE_VERSION.
 */
export const migrations: Record<number, (doc: Record<string, unknown>, catalog: Catalog) => Record<string, unknown>> = {
  1: migrateV1ToV2,
  2: migrateV2ToV3,
  3: migrateV3ToV4,
  4: migrateV4ToV5,
  5: migrateV5ToV6,
  6: migrateV6ToV7,
  7: migrateV7ToV8,
  8: migrateV8ToV9,
};

export function migrateSceneFile(doc: Record<string, unknown>, catalog: Catalog): Record<string, unknown> {
  let d = doc;
  // A room shape in any older file is refused naming the version the file says (the steps before 8 → 9 do not look at the room).
  if (typeof d.version === 'number' && d.version < 9) refuseV9Fields(d, d.version);
  while (typeof d.version === 'number' && d.version < SCENE_FILE_VERSION) {
    const step = migrations[d.version];
    if (!step) throw new SceneFileError(`scene file version ${d.version} is no longer supported`, { code: 'fileVersionUnsupported', params: { version: d.version } });
    d = step(d, catalog);
  }
  return d;
}
