import { engineProgress } from './engineProgress';
import { fromKey, ownWeight, targetKey } from './engineWeights';
import { weightedBases } from './groupState';
import type { StartedSolve } from './indirectSolver';
import { weightedFlux } from './reflectedFlux';
import type { RelightEngineState } from './relightEngineState';
import { sumDirect } from './relightMaps';
import type { EngineProgress } from './RelightEngine';

export function progressOf(st: RelightEngineState): EngineProgress {
  const { order, cache, fade, solver } = st;
  return engineProgress(order.length, order.filter((s) => s.basis).length, cache.isExact(targetKey(st)), !fade || cache.isExact(fromKey(st)), solver.fraction());
}

/** Starts the shared solve at the scene's own weights: a fade's intermediate weights are never solved (the blend of the ends is exact). */
function startSolve(st: RelightEngineState): StartedSolve {
  const scene = st.scene!;
  const weighted = weightedBases(st.order, (s) => ownWeight(st, s));
  const direct = sumDirect(weighted, st.layouts, st.atlas);
  const objects = scene.objects && scene.objects.length > 0 && direct.objects ? { objects: scene.objects, direct: direct.objects } : undefined;
  st.counters.indirectSolves++;
  const job = st.baker.startFromDirect(scene.room, direct.surfaces, st.settings, objects);
  return { job, flux: weightedFlux(weighted.map((p) => ({ flux: p.basis.flux, weight: p.weight }))) };
}

/** Direct bases for every new group first, one group per two calls (issue, then read back), so a caller slicing the work stays responsive; then the solve. */
export function stepEngine(st: RelightEngineState, samples: number, preview: boolean): EngineProgress {
  if (!st.scene || st.bases.advance(st.scene, st.order, st.states)) return progressOf(st);
  const key = targetKey(st);
  if (!st.cache.isExact(key) && st.solver.advance(key, () => startSolve(st), samples, preview)) st.version++;
  return progressOf(st);
}
