import type { IndirectSolution } from './relightMaps';

/**
 * Finished indirect solutions kept, by weights key (least recently used dropped first): a recalled
 * light scene whose weights were solved before is exact at once, and a crossfade between two solved
 * scenes blends their solutions. One solution is the room's indirect maps (about 0.5 MB for a
 * 5 × 4 m room at the viewer's 5 cm texels, plus the objects' atlas), so 8 stay well under 20 MB.
 */
export const SOLUTION_CACHE_SIZE = 8;

/** The finished solves of one room, by weights key (groupState.ts weightsKey); the key '' (no light at all) needs none. */
export interface SolutionCache {
  /** No light (key '') has exactly no indirect light; otherwise whether the solve at `key` is kept. */
  isExact(key: string): boolean;
  /** The solution at `key`, marked as the latest used; null for no light, undefined when not kept. */
  recall(key: string): IndirectSolution | null | undefined;
  /** Keeps a finished solution, dropping the least recently used beyond `capacity`. */
  remember(solution: IndirectSolution): void;
  clear(): void;
}

/** A least-recently-used cache of finished solutions: a Map's insertion order is its use order. */
export function createSolutionCache(capacity = SOLUTION_CACHE_SIZE): SolutionCache {
  const finals = new Map<string, IndirectSolution>();
  return {
    isExact: (key) => key === '' || finals.has(key),
    recall(key) {
      if (key === '') return null;
      const sol = finals.get(key);
      if (sol) {
        finals.delete(key);
        finals.set(key, sol);
      }
      return sol;
    },
    remember(sol) {
      finals.delete(sol.key);
      finals.set(sol.key, sol);
      while (finals.size > capacity) finals.delete(finals.keys().next().value!);
    },
    clear: () => finals.clear(),
  };
}
