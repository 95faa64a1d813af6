import type { BakeObject } from '../bakeScene';
import { prepareObjects } from './prepareObjects';
import type { PreparedObjects } from './preparedObjects';

/**
 * prepareObjects, remembered per objects list (by reference) and atlas options. The relighting
 * engine bakes one scene per module group with the same `objects` array, so the charts, atlas
 * G-buffer and BVH are built once per furnished layout instead of once per module. The result is
 * read-only data (prepareObjects is deterministic); the cache lets go of a list nobody holds.
 */
const cache = new WeakMap<readonly BakeObject[], Map<string, PreparedObjects>>();

export function prepareObjectsCached(objects: readonly BakeObject[], options: { texelSize: number; maxAtlasSize?: number }): PreparedObjects {
  const key = `${options.texelSize}|${options.maxAtlasSize ?? ''}`;
  let perOptions = cache.get(objects);
  if (!perOptions) {
    perOptions = new Map();
    cache.set(objects, perOptions);
  }
  let prepared = perOptions.get(key);
  if (!prepared) {
    prepared = prepareObjects([...objects], options);
    perOptions.set(key, prepared);
  }
  return prepared;
}
