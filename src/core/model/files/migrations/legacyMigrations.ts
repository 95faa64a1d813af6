/**
 * The steps from configuration files older than version 8 (migrateSceneFile.ts, LEGACY_BELOW): by
 * now rare, so they travel in the lazy chunk with rooms of any shape (roomShapeChunk.ts) instead of
 * the first screen, and every reader that may meet such a file loads that chunk first
 * (sceneTextNeedsLazyModel, roomShapeSupport.ts).
 */
import type { MigrationStep } from '../../configuration/roomShapeSupport';
import { migrateV1ToV2 } from './migrateV1ToV2';
import { migrateV2ToV3 } from './migrateV2ToV3';
import { migrateV3ToV4 } from './migrateV3ToV4';
import { migrateV4ToV5 } from './migrateV4ToV5';
import { migrateV5ToV6 } from './migrateV5ToV6';
import { migrateV6ToV7 } from './migrateV6ToV7';
import { migrateV7ToV8 } from './migrateV7ToV8';

export const legacyMigrations: Record<number, MigrationStep> = {
  1: migrateV1ToV2,
  2: migrateV2ToV3,
  3: migrateV3ToV4,
  4: migrateV4ToV5,
  5: migrateV5ToV6,
  6: migrateV6ToV7,
  7: migrateV7ToV8,
};
