import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import type { Catalog } from '../../../src/core/model/catalogSchema/catalogSchema';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration, type Joint, type LightSystem, type Rail, type Room } from '../../../src/core/model/configuration/configuration';

export const catalog: Catalog = defaultCatalog;

/** Performs an action after asserting it is enabled (test helper). */
export function run(state: Configuration, name: string, params: unknown, cat: Catalog = catalog): Configuration {
  const a = bindAction(name, params, cat);
  const e = a.isEnabled(state);
  if (e !== true) throw new Error(`${name} ${JSON.stringify(params)} refused: ${e.reason}`);
  return a.perform(state);
}

export function enabled(state: Configuration, name: string, params: unknown, cat: Catalog = catalog) {
  return bindAction(name, params, cat).isEnabled(state);
}

/** A room with one preset placed at the given anchor and heading. */
export function withPreset(presetId: string, x: number, z: number, rotation = 0, room = { width: 8, depth: 6, height: 3 }): Configuration {
  return run(createConfiguration(room), 'placePreset', { presetId, x, z, rotation });
}

export function only(config: Configuration): LightSystem {
  if (config.systems.length !== 1) throw new Error('expected one system');
  return config.systems[0];
}

/** `systems` rows of `railsPer` 1 m rails joined straight, one row per metre: a 30 × 30 m hall. */
export function hall(systems: number, railsPer: number, gap = 1): Configuration {
  let next = 1;
  const list: LightSystem[] = [];
  for (let k = 0; k < systems; k++) {
    list.push({
      id: `s${next++}`,
      x: 0.5,
      z: 0.5 + k * gap,
      rotation: 0,
      suspension: catalog.suspension.default,
      rails: Array.from({ length: railsPer }, () => ({ id: `r${next++}`, length: 1, distribution: 'start' as const, modules: [] })),
      joints: Array.from({ length: railsPer - 1 }, () => ({ connector: 'straight', turn: 0 })),
      feeds: [],
      mounting: 'suspended',
    });
  }
  // Feed ids after all the others, so systems and rails keep the numbers they had before feeds.
  const fed = list.map((s) => ({ ...s, feeds: [{ id: `f${next++}`, at: 'start' as const, driver: catalog.feed.defaultDriver }] }));
  return { ...createConfiguration({ width: 30, depth: 30, height: 3 }), systems: fed, nextId: next };
}

/** Every system fed from both chain ends by the catalog's largest driver (2 × 321.6 W): room for a full rail of spots. */
export function powered(config: Configuration, cat: Catalog = catalog): Configuration {
  const largest = [...cat.drivers].sort((a, b) => b.capacity - a.capacity)[0].id;
  let s = config;
  for (const sys of config.systems) {
    for (const f of sys.feeds) s = run(s, 'setFeedDriver', { feedId: f.id, driver: largest }, cat);
    if (!sys.feeds.some((f) => f.at === 'end')) s = run(s, 'addFeed', { systemId: sys.id, at: 'end', driver: largest }, cat);
  }
  return s;
}

/**
 * A configuration with one suspended system 's1' at (1, 1) heading +x: the given rails and
 * joints, one feed `feedId` at the chain start with the catalog's default driver; `nextId` the
 * next free id number (the fixtures of the free-placement, drag and fixing-point tests).
 */
export function systemAtOneOne(rails: Rail[], joints: Joint[], feedId: string, nextId: number, room: Partial<Room> = {}): Configuration {
  const system: LightSystem = {
    id: 's1',
    x: 1,
    z: 1,
    rotation: 0,
    suspension: catalog.suspension.default,
    rails,
    joints,
    feeds: [{ id: feedId, at: 'start', driver: catalog.feed.defaultDriver }],
    mounting: 'suspended',
  };
  return { ...createConfiguration(room), systems: [system], nextId };
}
