/** Scene file version 2 → 3 (what version 3 added; docs/model.md). */
import { needsVersion } from '../sceneFileError';
import { refuseV4Fields } from './migrateV3ToV4';
import { refuseV5Fields } from './migrateV4ToV5';
import { refuseV6Fields } from './migrateV5ToV6';
import { refuseV7Fields } from './migrateV6ToV7';
import { refuseV8Fields } from './migrateV7ToV8';

/**
 * 2 → 3: version 3 added objects and imported meshes; a version 2 configuration has none.
 */
export function migrateV2ToV3(doc: Record<string, unknown>): Record<string, unknown> {
  const c = doc.configuration;
  for (const key of ['objects', 'importedMeshes']) {
    if (typeof c === 'object' && c !== null && key in c) throw needsVersion(`configuration.${key}`, 3, 2);
  }
  refuseV4Fields(doc, 2);
  refuseV5Fields(doc, 2);
  refuseV6Fields(doc, 2);
  refuseV7Fields(doc, 2);
  refuseV8Fields(doc, 2);
  return { ...doc, version: 3 };
}
