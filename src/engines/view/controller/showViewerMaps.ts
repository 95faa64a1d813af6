import { reflectanceRgb } from '../../bake/bakeScene';
import type { RelightEngine } from '../../relight/RelightEngine';
import { sceneAdoptedWhite } from '../adoptedWhite';
import { applyLiveLevels } from '../applyLiveLevels';
import { sceneGeometryKey } from '../sceneGeometryKey';
import { showCompare } from './compareSides';
import { luminaireWeight } from '../luminaireWeight';
import { syncGlare, type Viewer } from './viewer';
import { cancelSettle, noteCpuShow, showRelightOnGpu } from './gpuRelightFrame';

/** The engine's maps on screen (both compare sides during the A/B compare), glare as the bake's progress says. */
export function showMaps(v: Viewer, engine: RelightEngine): void {
  if (!v.scene) return;
  v.lightDone = engine.progress.done;
  syncGlare(v);
  if (v.compare && showCompare(v, engine, v.compare)) {
    v.shownVersion = engine.version;
    v.frames.request();
    return;
  }
  if (!showRelightOnGpu(v, engine, () => showOnCpu(v, engine))) showOnCpu(v, engine);
  syncWeights(v);
  v.shownVersion = engine.version;
  v.frames.request();
}

/** The engine's maps summed on the CPU (engine.maps()) and uploaded: new geometry, the eye adapting, the compare, or a settled GPU relight stream. */
function showOnCpu(v: Viewer, engine: RelightEngine): void {
  if (!v.scene) return;
  cancelSettle(v.gpu);
  const t0 = performance.now();
  const lit = engine.maps();
  const key = sceneGeometryKey(v.scene);
  v.maps.show(lit, reflectanceRgb(v.scene.room), t0, { white: sceneAdoptedWhite(v.scene, v.service.lightSources), key, done: engine.progress.done });
  noteCpuShow(v.gpu, lit, key);
  v.frames.request();
}

/**
 * The glow follows the light shown (dimming, live levels, a crossfade's mix: the service's
 * weights), except the module the spotlight preview lights from the shader: the maps leave it
 * out, its lamp still shines (its weight with the live levels).
 */
export function syncWeights(v: Viewer): void {
  // During the A/B compare each side shows its own scene's glow (showCompare).
  if (v.compare) return;
  const { scene, ids, live, dimmed } = v;
  const weights = v.service.luminaireWeights();
  if (!weights || !scene || v.service.scene !== scene) return;
  const k = dimmed ? ids.indexOf(dimmed) : -1;
  const own = k >= 0 ? (live ? applyLiveLevels(scene, ids, live) : scene).luminaires[k] : undefined;
  if (own) weights[k] = luminaireWeight(own);
  v.view.setModuleWeights(new Map(weights.flatMap((w, i) => (ids[i] ? [[ids[i], w] as const] : []))));
}

/** The service's objects layout on screen (it changes with the objects and with the quality's texel size). */
export function syncObjects(v: Viewer): void {
  const next = v.service.objects();
  if (next === v.prepared) return;
  // New or moved objects: their old light belongs to another atlas; they show again with the new bake's first maps.
  v.prepared = next;
  v.view.setObjects(v.prepared);
  v.compareView?.setObjects(v.prepared);
  v.shownVersion = -1;
}

/** The bake counters the progress event carries. */
export function bakeCounters(v: Viewer): { groupBakes: number; relightsOnly: number; indirectSolves: number } {
  const { groupBakes, relightsOnly, indirectSolves } = v.service.status();
  return { groupBakes, relightsOnly, indirectSolves };
}
