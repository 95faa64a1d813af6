import { surfaceLayouts } from '../bake/surfaceLayout';
import { fromKey, shownWeight, targetKey } from './engineWeights';
import { weightedBases, weightsKey } from './groupState';
import { indirectTerms } from './indirectTerms';
import type { RelightEngineState } from './relightEngineState';
import { emptyLitMaps, relightMaps, type LitMaps } from './relightMaps';
import type { RelightParts } from './RelightEngine';

/** What the maps shown are made of: the shown weights of the baked groups and the indirect terms (exact, blend or Φ-scaled). */
export function relightPartsOf(st: RelightEngineState): RelightParts | null {
  if (!st.scene || !st.out) return null;
  const weight = (s: Parameters<typeof shownWeight>[1]) => shownWeight(st, s);
  const parts = weightedBases(st.order, weight);
  const fadeKeys = st.fade ? { fromKey: fromKey(st), toKey: targetKey(st), e: st.fade.e } : null;
  return { parts, terms: indirectTerms(weightsKey(st.order, weight), parts, st.cache, st.solver.latest, fadeKeys), layouts: st.out.layouts, atlas: st.atlas, version: st.version, fade: st.fade ? st.fade.e : null };
}

/** The relit maps of the weights shown, summed again only when the version moved. */
export function composeMaps(st: RelightEngineState): LitMaps {
  if (!st.out) st.out = emptyLitMaps(surfaceLayouts({ width: 1, height: 1, depth: 1 }, st.settings.texelSize, st.settings.maxTextureSize));
  if (st.composedVersion === st.version || !st.scene) return st.out;
  const { parts, terms } = relightPartsOf(st)!;
  relightMaps(parts, terms, st.atlas, st.out);
  st.counters.relights++;
  st.composedVersion = st.version;
  return st.out;
}
