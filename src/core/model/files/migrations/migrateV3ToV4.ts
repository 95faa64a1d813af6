/** Scene file version 3 → 4 (what version 4 added; docs/model.md). */
import type { Catalog } from '../../catalogSchema/catalogSchema';
import type { LightSystem } from '../../configuration/configuration';
import { needsVersion } from '../sceneFileError';
import { plannedFeeds } from '../../power/feedLoads';
import { refuseV5Fields } from './migrateV4ToV5';
import { refuseV6Fields } from './migrateV5ToV6';
import { refuseV7Fields } from './migrateV6ToV7';
import { refuseV8Fields } from './migrateV7ToV8';

/**
 * 3 → 4: version 4 added power feeds and the mounting. An older system hung on suspensions and had
 * one feed kit: it gets `mounting: 'suspended'` and the feeds a new system of its shape gets
 * (plannedFeeds: one at the chain start with the catalog's default driver, or what its load needs),
 * with ids from nextId. Anything the schema would refuse is left as it is, for the schema to name.
 */
export function migrateV3ToV4(doc: Record<string, unknown>, catalog: Catalog): Record<string, unknown> {
  const c = doc.configuration;
  if (typeof c !== 'object' || c === null || !Array.isArray((c as Record<string, unknown>).systems)) return { ...doc, version: 4 };
  refuseV4Fields(doc, 3);
  refuseV5Fields(doc, 3);
  refuseV6Fields(doc, 3);
  refuseV7Fields(doc, 3);
  refuseV8Fields(doc, 3);
  const conf = c as Record<string, unknown>;
  let nextId = typeof conf.nextId === 'number' && Number.isInteger(conf.nextId) ? conf.nextId : null;
  const systems = (conf.systems as unknown[]).map((raw) => {
    if (typeof raw !== 'object' || raw === null) return raw;
    const sys = { ...(raw as Record<string, unknown>), mounting: 'suspended' };
    if (nextId === null) return sys;
    let feeds: { at: unknown; driver: string }[];
    try {
      feeds = plannedFeeds({ ...(sys as unknown as LightSystem), feeds: [] }, catalog);
    } catch {
      // Unknown connectors or module types: a plain default feed, and validate() names the real problem.
      feeds = [{ at: 'start', driver: catalog.feed.defaultDriver }];
    }
    return { ...sys, feeds: feeds.map((f) => ({ id: `f${nextId!++}`, ...f })) };
  });
  return { ...doc, version: 4, configuration: { ...conf, systems, ...(nextId === null ? {} : { nextId }) } };
}

/** Feeds and mounting came with version 4: a file that says it is older and has them was not written by luxbox. */
export function refuseV4Fields(doc: Record<string, unknown>, version: number): void {
  const c = doc.configuration;
  const systems = typeof c === 'object' && c !== null && Array.isArray((c as Record<string, unknown>).systems) ? ((c as Record<string, unknown>).systems as unknown[]) : [];
  systems.forEach((s, i) => {
    for (const key of ['feeds', 'mounting']) {
      if (typeof s === 'object' && s !== null && key in s) throw needsVersion(`configuration.systems[${i}].${key}`, 4, version);
    }
  });
}
