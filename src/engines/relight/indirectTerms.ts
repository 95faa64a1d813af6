import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { indirectScale, weightedFlux } from './reflectedFlux';
import type { IndirectSolution, IndirectTerm, WeightedBasis } from './relightMaps';
import type { SolutionCache } from './solutionCache';

/** A crossfade as the indirect light sees it: the weights keys of its two ends and the fraction `e` (docs/light-scenes.md). */
export interface FadeKeys {
  fromKey: string;
  toKey: string;
  e: number;
}

/**
 * The indirect light shown at the weights `key` of the `weighted` bases. A fade between two solved
 * weightings is their blend, exact since the indirect light is linear in the weights; weights solved
 * before (final, or a preview of the first solve in `latest`) are shown as solved; otherwise the
 * last solve is scaled per channel by the reflected direct flux Φ_now/Φ_solve (reflectedFlux.ts).
 * No light (key '') has no indirect light.
 */
export function indirectTerms(key: string, weighted: readonly WeightedBasis[], cache: SolutionCache, latest: IndirectSolution | null, fade: FadeKeys | null): IndirectTerm[] {
  if (key === '') return [];
  const ends = fade ? [cache.recall(fade.fromKey), cache.recall(fade.toKey)] : null;
  if (fade && ends && ends[0] !== undefined && ends[1] !== undefined) {
    const [a, b] = ends;
    const e = fade.e;
    return [...(a ? [{ solution: a, scale: [1 - e, 1 - e, 1 - e] as Rgb }] : []), ...(b ? [{ solution: b, scale: [e, e, e] as Rgb }] : [])];
  }
  const exact = cache.recall(key) ?? (latest?.key === key ? latest : null);
  if (exact) return [{ solution: exact, scale: [1, 1, 1] }];
  if (latest) return [{ solution: latest, scale: indirectScale(weightedFlux(weighted.map((p) => ({ flux: p.basis.flux, weight: p.weight }))), latest.flux) }];
  return [];
}
