/** Scene file version 7 → 8 (what version 8 added; docs/model.md). */
import { needsVersion } from '../sceneFileError';

/**
 * 7 → 8: version 8 made a system a tree of rails; a version 7 system is a snake, which is a tree
 * whose every joint hangs on the rail before it (no `parent`) and whose feeds sit at the start,
 * the end or a connector, so the content reads as is, exactly.
 */
export function migrateV7ToV8(doc: Record<string, unknown>): Record<string, unknown> {
  refuseV8Fields(doc, 7);
  return { ...doc, version: 8 };
}

/** Branches (a joint's `parent`) and feeds at a branch end came with version 8: an older file that has them was not written by luxbox. */
export function refuseV8Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const list = (o: unknown, key: string): unknown[] => (typeof o === 'object' && o !== null && Array.isArray((o as Record<string, unknown>)[key]) ? ((o as Record<string, unknown>)[key] as unknown[]) : []);
  list(c, 'systems').forEach((sys, i) => {
    list(sys, 'joints').forEach((j, k) => {
      if (typeof j === 'object' && j !== null && 'parent' in j) throw needsVersion(`configuration.systems[${i}].joints[${k}].parent`, 8, version);
    });
    list(sys, 'feeds').forEach((f, k) => {
      const at = typeof f === 'object' && f !== null ? (f as Record<string, unknown>).at : undefined;
      if (typeof at === 'object' && at !== null && 'end' in at) throw needsVersion(`configuration.systems[${i}].feeds[${k}].at.end`, 8, version);
    });
  });
}
