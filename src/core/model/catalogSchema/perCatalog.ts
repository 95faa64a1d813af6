/**
 * Memoising pure derived data of immutable model objects (a system, a configuration) per catalog.
 * States are never changed in place (actions build new objects and keep the untouched ones, see
 * validateResult.ts), so a value derived from an object and a catalog stays right for as long as
 * the object lives; WeakMaps let both go with the states that hold them. A computation that throws
 * is not remembered (the next call throws again).
 */
import type { Catalog } from './catalogSchema';

/** `compute` remembered per (catalog, object): the second call with the same two returns the first call's value. */
export function perCatalog<K extends object, V>(compute: (key: K, catalog: Catalog) => V): (key: K, catalog: Catalog) => V {
  const byCatalog = new WeakMap<Catalog, WeakMap<K, V>>();
  return (key, catalog) => {
    let known = byCatalog.get(catalog);
    if (!known) byCatalog.set(catalog, (known = new WeakMap()));
    if (known.has(key)) return known.get(key) as V;
    const value = compute(key, catalog);
    known.set(key, value);
    return value;
  };
}
