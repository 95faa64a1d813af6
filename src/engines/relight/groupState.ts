import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { LuminaireGroup } from './luminaireGroups';
import type { DirectBasis, WeightedBasis } from './relightMaps';

/** A luminaire group of the scene and its direct basis once baked (null until then). */
export interface GroupState {
  group: LuminaireGroup;
  basis: DirectBasis | null;
}

/** A weight per group: the scene's own, the faded-from scene's, or a blend of the two. */
export type GroupWeight = (s: GroupState) => Rgb;

/** The groups that are shown (basis baked) with the given weights. */
export function weightedBases(order: readonly GroupState[], weight: GroupWeight): WeightedBasis[] {
  return order.filter((s) => s.basis).map((s) => ({ basis: s.basis!, weight: weight(s) }));
}

/**
 * The weights the indirect light depends on: every lit group with its RGB weight (order-free;
 * '' = no light at all). Solutions are solved, cached and recalled by this key.
 */
export function weightsKey(order: readonly GroupState[], weight: GroupWeight): string {
  return order
    .map((s) => [s.group.key, weight(s)] as const)
    .filter(([, w]) => w.some((v) => v > 0))
    .map(([k, w]) => `${k}=${w.join(',')}`)
    .sort()
    .join('|');
}

/** A crossfade's weight at fraction `e`: (1 − e)·from + e·to per channel (docs/light-scenes.md). */
export function blendWeights(from: Rgb, to: Rgb, e: number): Rgb {
  return [(1 - e) * from[0] + e * to[0], (1 - e) * from[1] + e * to[1], (1 - e) * from[2] + e * to[2]];
}

/**
 * The states of a scene's `groups`: a group already in `states` (same geometry key) keeps its
 * basis, a new one has none yet. `bake` counts the new ones; `order` follows `groups`.
 */
export function reconcileGroups(states: ReadonlyMap<string, GroupState>, groups: readonly LuminaireGroup[]): { states: Map<string, GroupState>; order: GroupState[]; bake: number } {
  const kept = new Map<string, GroupState>();
  let bake = 0;
  for (const g of groups) {
    const old = states.get(g.key);
    if (old) kept.set(g.key, { ...old, group: g });
    else {
      kept.set(g.key, { group: g, basis: null });
      bake++;
    }
  }
  return { states: kept, order: groups.map((g) => kept.get(g.key)!), bake };
}
