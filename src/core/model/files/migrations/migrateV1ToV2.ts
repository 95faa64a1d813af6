/** Scene file version 1 → 2 (what version 2 added; docs/model.md). */
import { firstModuleWith } from './firstModuleWith';
import { needsVersion } from '../sceneFileError';
import { refuseV4Fields } from './migrateV3ToV4';
import { refuseV5Fields } from './migrateV4ToV5';
import { refuseV6Fields } from './migrateV5ToV6';
import { refuseV7Fields } from './migrateV6ToV7';
import { refuseV8Fields } from './migrateV7ToV8';

/**
 * 1 → 2: version 2 added the optional DMX patch per module; a version 1 module has none, so its
 * content reads as is. A `dmx` field in a version 1 file was never written by luxbox: refused.
 */
export function migrateV1ToV2(doc: Record<string, unknown>): Record<string, unknown> {
  const at = v1PatchField(doc.configuration);
  if (at) throw needsVersion(`configuration.${at}`, 2, 1);
  const c = doc.configuration;
  for (const key of ['objects', 'importedMeshes']) {
    if (typeof c === 'object' && c !== null && key in c) throw needsVersion(`configuration.${key}`, 3, 1);
  }
  refuseV4Fields(doc, 1);
  refuseV5Fields(doc, 1);
  refuseV6Fields(doc, 1);
  refuseV7Fields(doc, 1);
  refuseV8Fields(doc, 1);
  return { ...doc, version: 2 };
}

/** Path of the first module carrying `dmx` in a version 1 configuration (its shape is checked later, so every step looks before it leaps). */
function v1PatchField(configuration: unknown): string | null {
  return firstModuleWith(configuration, 'dmx');
}
