/** Scene file version 5 → 6 (what version 6 added; docs/model.md). */
import { needsVersion } from '../sceneFileError';
import { refuseV7Fields } from './migrateV6ToV7';
import { refuseV8Fields } from './migrateV7ToV8';

/**
 * 5 → 6: version 6 added moved fixing points and flexible connectors; a version 5 system's
 * fixing points are the derived ones and its joints turn by a fixed angle, so it reads as is.
 */
export function migrateV5ToV6(doc: Record<string, unknown>): Record<string, unknown> {
  refuseV6Fields(doc, 5);
  refuseV7Fields(doc, 5);
  refuseV8Fields(doc, 5);
  return { ...doc, version: 6 };
}

/** Moved fixing points came with version 6: a file that says it is older and has them was not written by luxbox. */
export function refuseV6Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const systems = typeof c === 'object' && c !== null && Array.isArray((c as Record<string, unknown>).systems) ? ((c as Record<string, unknown>).systems as unknown[]) : [];
  systems.forEach((s, i) => {
    if (typeof s === 'object' && s !== null && 'fixings' in s) throw needsVersion(`configuration.systems[${i}].fixings`, 6, version);
  });
}
