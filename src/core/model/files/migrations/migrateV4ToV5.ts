/** Scene file version 4 → 5 (what version 5 added; docs/model.md). */
import { firstModuleWith } from './firstModuleWith';
import { needsVersion } from '../sceneFileError';
import { refuseV6Fields } from './migrateV5ToV6';
import { refuseV7Fields } from './migrateV6ToV7';
import { refuseV8Fields } from './migrateV7ToV8';

/**
 * 4 → 5: version 5 added free module positions; a version 4 module has none (its rail's
 * distribution places it), so the content reads as is.
 */
export function migrateV4ToV5(doc: Record<string, unknown>): Record<string, unknown> {
  refuseV5Fields(doc, 4);
  refuseV6Fields(doc, 4);
  refuseV7Fields(doc, 4);
  refuseV8Fields(doc, 4);
  return { ...doc, version: 5 };
}

/** Free positions came with version 5: a file that says it is older and has one was not written by luxbox. */
export function refuseV5Fields(doc: Record<string, unknown>, version: number): void {
  const at = firstModuleWith(doc.configuration, 'offset');
  if (at) throw needsVersion(`configuration.${at}`, 5, version);
}
