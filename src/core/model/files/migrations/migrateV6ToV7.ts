/** Scene file version 6 → 7 (what version 7 added; docs/model.md). */
import { firstModuleWith } from './firstModuleWith';
import { needsVersion } from '../sceneFileError';
import { refuseV8Fields } from './migrateV7ToV8';

/**
 * 6 → 7: version 7 added on/off, filters and aims per module and light scenes; a version 6 module
 * is on, unfiltered and points straight down, and there are no scenes, so the content reads as is.
 */
export function migrateV6ToV7(doc: Record<string, unknown>): Record<string, unknown> {
  refuseV7Fields(doc, 6);
  refuseV8Fields(doc, 6);
  return { ...doc, version: 7 };
}

/** On/off, filters, aims and light scenes came with version 7: an older file that has them was not written by luxbox. */
export function refuseV7Fields(doc: Record<string, unknown>, version: number): void {
  for (const key of ['on', 'filter', 'aim']) {
    const at = firstModuleWith(doc.configuration, key);
    if (at) throw needsVersion(`configuration.${at}`, 7, version);
  }
  const c = doc.configuration;
  if (typeof c === 'object' && c !== null && 'lightScenes' in c) throw needsVersion(`configuration.lightScenes`, 7, version);
}
