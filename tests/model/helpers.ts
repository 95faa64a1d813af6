import { defaultCatalog } from '../../src/catalog/defaultCatalog';
import type { Catalog } from '../../src/model/catalogSchema';
import { bindAction } from '../../src/model/actionDefinitions';
import { createConfiguration, type Configuration, type LightSystem } from '../../src/model/configuration';

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
