import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import type { BakeScene } from '../bake/bakeScene';
import { blendWeights, weightsKey, type GroupState } from './groupState';
import { groupLuminaires, groupWeight } from './luminaireGroups';
import type { RelightEngineState } from './relightEngineState';

const OFF: Rgb = [0, 0, 0];
const WHITE: Rgb = [1, 1, 1];

/** The group keys of a luminaire list, in order: a fade's two scenes must have the same. */
export const electricGroupKeys = (sc: BakeScene): string =>
  groupLuminaires(sc.luminaires)
    .map((g) => g.key)
    .join('|');

/** The keys of the luminaire groups among `order` (the daylight groups left out: daylight does not fade). */
export const electricOrderKeys = (order: readonly GroupState[]): string =>
  order
    .filter((s) => !s.group.daylight)
    .map((s) => s.group.key)
    .join('|');

/**
 * A group's weight with the luminaires of `luminaires` under the sources shown: a luminaire group
 * Σ dimming·colour of its members, a daylight group 1 (its basis is the daylight itself); 0 for
 * the light the sources leave out ('electric': daylight off, 'daylight': luminaires off,
 * 'daylight-factor': everything but the overcast basis off).
 */
function sourceWeight(st: RelightEngineState, s: GroupState, luminaires: BakeScene['luminaires']): Rgb {
  const daylight = s.group.daylight;
  // The daylight factor's overcast basis alone, or never.
  if (st.sources === 'daylight-factor') return daylight?.kind === 'overcast' ? WHITE : OFF;
  if (daylight) return st.sources === 'electric' || daylight.kind === 'overcast' ? OFF : WHITE;
  return st.sources === 'daylight' ? OFF : groupWeight(s.group, luminaires);
}

/** A group's weight in the scene itself (the end of a fade). */
export const ownWeight = (st: RelightEngineState, s: GroupState): Rgb => sourceWeight(st, s, st.scene!.luminaires);

/** A group's weight in the scene faded from (daylight is the scene's: a fade changes only the luminaires). */
export const fromWeight = (st: RelightEngineState, s: GroupState): Rgb => sourceWeight(st, s, st.fade!.from.luminaires);

/** A group's weight as shown: the fade's blend, or the scene's own. */
export const shownWeight = (st: RelightEngineState, s: GroupState): Rgb => (st.fade ? blendWeights(fromWeight(st, s), ownWeight(st, s), st.fade.e) : ownWeight(st, s));

/** The weights key of the scene itself: what a solve works toward. */
export const targetKey = (st: RelightEngineState): string => weightsKey(st.order, (s) => ownWeight(st, s));

/** The weights key of the scene faded from. */
export const fromKey = (st: RelightEngineState): string => weightsKey(st.order, (s) => fromWeight(st, s));
