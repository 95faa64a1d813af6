import type { DirectBasis } from './relightMaps';

/**
 * Bytes the daylight bases kept out of the scene may hold (docs/daylight.md, "Daylight in the relight
 * engine"): 16 MiB, a quarter of the view's texture budget on low-memory devices
 * (LOW_MEMORY_RELIGHT_BYTES, 64 MiB, engines/view/createViewRelight.ts), so the kept bases and the
 * scene's own bases, solutions and display targets fit such a device together. The daylight box of
 * the tests (5 × 4 × 2.8 m, one window) at the viewer's 5 cm texels takes 1 042 KiB a basis
 * (measured, tests/engines/relight/daylightBasisCache.test.ts): 15 bases, 7 times of day with their
 * sky and sun.
 */
export const DAYLIGHT_BASIS_CACHE_BYTES = 16 * 1024 * 1024;

/**
 * Daylight bases whose group left the scene (another time of day, date, place or sky; the daylight
 * factor's overcast basis when its mode is left), by group key (daylightGroups.ts: the key holds
 * everything the basis depends on but the room and objects, whose change clears the cache). A group
 * that comes back takes its basis again instead of a rebake: a time slider moved back to a time
 * already seen re-weights at once. Least recently kept dropped first beyond the budget.
 */
export interface DaylightBasisCache {
  /** Keep the basis of a daylight group that left the scene (a basis larger than the budget is not kept). */
  keep(key: string, basis: DirectBasis): void;
  /** The basis kept for `key`, taken out of the cache (it is the scene's again); undefined when none is. */
  take(key: string): DirectBasis | undefined;
  clear(): void;
  /** Bases kept now, their bytes, and how many were dropped for the budget so far. */
  readonly size: number;
  readonly bytes: number;
  readonly evictions: number;
  readonly budget: number;
}

/** The bytes a basis holds: every map of it (walls, and the atlas as the bounces read it and as it is shown). */
export function basisBytes(basis: DirectBasis): number {
  let bytes = 0;
  for (const map of Object.values(basis.surfaces)) bytes += map.byteLength;
  if (basis.objects) bytes += basis.objects.emitted.byteLength + basis.objects.shown.byteLength;
  return bytes;
}

/** A least-recently-kept cache within `budget` bytes: a Map's insertion order is its age. */
export function createDaylightBasisCache(budget = DAYLIGHT_BASIS_CACHE_BYTES): DaylightBasisCache {
  const kept = new Map<string, { basis: DirectBasis; bytes: number }>();
  let bytes = 0;
  let evictions = 0;
  const remove = (key: string) => {
    const entry = kept.get(key);
    if (!entry) return undefined;
    kept.delete(key);
    bytes -= entry.bytes;
    return entry.basis;
  };
  return {
    keep(key, basis) {
      remove(key);
      const size = basisBytes(basis);
      if (size > budget) return;
      kept.set(key, { basis, bytes: size });
      bytes += size;
      while (bytes > budget) {
        remove(kept.keys().next().value!);
        evictions++;
      }
    },
    take: remove,
    clear() {
      kept.clear();
      bytes = 0;
    },
    get size() {
      return kept.size;
    },
    get bytes() {
      return bytes;
    },
    get evictions() {
      return evictions;
    },
    budget,
  };
}
