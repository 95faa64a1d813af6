import { reflectanceRgb, type BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import { resolveBakeSettings } from '../bake/bakeSettings';
import { createBaker } from '../bake/createBaker';
import { surfaceLayouts, type SurfaceLayout } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';
import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { createDirectBasisQueue } from './directBasisQueue';
import { engineProgress } from './engineProgress';
import { type GroupState, blendWeights, reconcileGroups, weightedBases, weightsKey } from './groupState';
import { createIndirectSolver } from './indirectSolver';
import { indirectTerms } from './indirectTerms';
import { groupLuminaires, groupWeight, roomKey } from './luminaireGroups';
import { objectsKey } from './objectsKey';
import { reflectedFlux, weightedFlux } from './reflectedFlux';
import type { EngineCounters, EngineFade, EngineProgress, RelightEngine, RelightParts, SetSceneResult } from './RelightEngine';
import { encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import { emptyLitMaps, relightMaps, sumDirect, type LitMaps } from './relightMaps';
import { createSolutionCache } from './solutionCache';

/**
 * Quality of the viewer's bakes (direct bases and the shared indirect solve): coarser texels
 * than the CLI default. 128 samples (not 64): on the corner-l
 * configuration the RMS error of the indirect light averaged over 25 cm
 * patches (the visible blotches) drops from 2.0 % to 1.4 % of a 1024-sample
 * reference, for 1.6× the bake time; a wider blur (8–10 texels) was cheaper
 * but measured worse (2.2–2.8 %: it flattens real gradients near corners and
 * lamps). docs/viewer.md, "Viewer bake quality".
 */
export const VIEWER_BAKE_SETTINGS: Partial<BakeSettings> = { texelSize: 0.05, maxTextureSize: 256, samples: 128, bounces: 3, samplesPerDraw: 8, blurRadius: 5 };

/** The group keys of a luminaire list, in order: a fade's two scenes must have the same. */
const groupKeys = (sc: BakeScene) =>
  groupLuminaires(sc.luminaires)
    .map((g) => g.key)
    .join('|');

/** Throws unless `fade` can be shown: a fraction in [0, 1], a scene to fade to, and the same luminaires (geometry) at both ends. */
function checkFade(fade: EngineFade, scene: BakeScene | null, order: readonly GroupState[]): void {
  if (!(fade.e >= 0 && fade.e <= 1)) throw new Error(`setFade: fraction ${fade.e} is outside [0, 1]`);
  if (!scene) throw new Error('setFade: no scene to fade to');
  if (groupKeys(fade.from) !== order.map((s) => s.group.key).join('|')) throw new Error('setFade: the scene faded from has other luminaires than the scene');
}

/**
 * The relight engine (RelightEngine.ts): the groups of the current scene and their bases
 * (directBasisQueue.ts bakes them), the shared indirect solve (indirectSolver.ts schedules it,
 * solutionCache.ts keeps the finished ones) and the relit maps composed from them on demand.
 */
export function createRelightEngine(gl: WebGL2RenderingContext, partial: Partial<BakeSettings> = VIEWER_BAKE_SETTINGS): RelightEngine {
  const settings = resolveBakeSettings(partial);
  const baker = createBaker(gl);
  const counters: EngineCounters = { groupBakes: 0, relightsOnly: 0, relights: 0, indirectSolves: 0 };
  let scene: BakeScene | null = null;
  let room = '';
  let layouts: SurfaceLayout[] = [];
  let atlas: ObjectAtlas | null = null;
  let states = new Map<string, GroupState>();
  let order: GroupState[] = [];
  let fade: EngineFade | null = null;
  let out: LitMaps | null = null;
  let version = 0;
  let composedVersion = -1;
  const cache = createSolutionCache();
  const solver = createIndirectSolver(cache, settings);
  // A basis is the direct pass alone: with no bounces the baker skips the bright patches, the gather and the flux record.
  // Its lamps are uniforms: a moved module, or another of the same type, reuses the compiled programs.
  const bases = createDirectBasisQueue(
    baker,
    { ...settings, bounces: 0, lampUniforms: true },
    () => counters.groupBakes++,
    (st, d) => {
      atlas = d.objects?.atlas ?? null;
      const flux = reflectedFlux(d.surfaces, layouts, reflectanceRgb(scene!.room), atlas, d.objects?.emitted ?? null);
      st.basis = { ...d, flux, luminaires: st.group.basis };
      version++;
    },
  );

  /** A group's weight in the scene itself (the end of a fade), in the scene faded from, and as shown. */
  const ownWeight = (s: GroupState) => groupWeight(s.group, scene!.luminaires);
  const fromWeight = (s: GroupState) => groupWeight(s.group, fade!.from.luminaires);
  const shownWeight = (s: GroupState): Rgb => (fade ? blendWeights(fromWeight(s), ownWeight(s), fade.e) : ownWeight(s));
  /** The weights key of the scene itself: what a solve works toward. */
  const targetKey = (): string => weightsKey(order, ownWeight);

  const progress = (): EngineProgress => engineProgress(order.length, order.filter((s) => s.basis).length, cache.isExact(targetKey()), !fade || cache.isExact(weightsKey(order, fromWeight)), solver.fraction());

  // The scene's own weights: a fade's intermediate weights are never solved (the blend of the ends is exact).
  const startSolve = () => {
    const weighted = weightedBases(order, ownWeight);
    const direct = sumDirect(weighted, layouts, atlas);
    const objects = scene!.objects && scene!.objects.length > 0 && direct.objects ? { objects: scene!.objects, direct: direct.objects } : undefined;
    counters.indirectSolves++;
    const job = baker.startFromDirect(scene!.room, direct.surfaces, settings, objects);
    return { job, flux: weightedFlux(weighted.map((p) => ({ flux: p.basis.flux, weight: p.weight }))) };
  };

  // Direct bases for every new group first, one group per two calls (issue, then read back), so a caller slicing the work stays responsive.
  const step = (samples = settings.samplesPerDraw, preview = true): EngineProgress => {
    if (!scene || bases.advance(scene, order, states)) return progress();
    const key = targetKey();
    if (!cache.isExact(key) && solver.advance(key, startSolve, samples, preview)) version++;
    return progress();
  };

  /** A new room (or other objects): every basis and solution is of another room. */
  const changeRoom = (next: BakeScene, nextRoom: string) => {
    solver.reset();
    bases.drop();
    cache.clear();
    atlas = null;
    states = new Map();
    room = nextRoom;
    layouts = surfaceLayouts(next.room, settings.texelSize, settings.maxTextureSize);
    out = emptyLitMaps(layouts);
  };

  const setScene = (given: BakeScene): SetSceneResult => {
    // A room of any shape is lit inside its enclosure, as the baker bakes it (remembered per shape and objects: one atlas).
    const next = encloseShapedRoom(given);
    // Objects are part of the room: moving, adding or removing one is a new scene and rebakes every group.
    const nextRoom = roomKey(next.room) + objectsKey(next.objects);
    if (nextRoom !== room) changeRoom(next, nextRoom);
    scene = next;
    const groups = groupLuminaires(next.luminaires);
    const reconciled = reconcileGroups(states, groups);
    states = reconciled.states;
    order = reconciled.order;
    const { bake } = reconciled;
    // A basis under way for a group that is gone (moved, removed) is of no use.
    bases.keepOnly(states);
    // A fade from a scene with other luminaires (a module added or moved meanwhile) cannot be shown: the scene is.
    if (fade && groupKeys(fade.from) !== groups.map((g) => g.key).join('|')) fade = null;
    // A solve under way for other weights is of no use any more (the shown one stays until the new solve is done).
    solver.dropUnless(targetKey());
    if (bake === 0) counters.relightsOnly++;
    version++;
    return { bake, reused: groups.length - bake };
  };

  /** What the maps shown are made of: the shown weights of the baked groups and the indirect terms (exact, blend or Φ-scaled). */
  const relightParts = (): RelightParts | null => {
    if (!scene || !out) return null;
    const parts = weightedBases(order, shownWeight);
    const fadeKeys = fade ? { fromKey: weightsKey(order, fromWeight), toKey: targetKey(), e: fade.e } : null;
    return { parts, terms: indirectTerms(weightsKey(order, shownWeight), parts, cache, solver.latest, fadeKeys), layouts: out.layouts, atlas, version, fade: fade ? fade.e : null };
  };

  const maps = (): LitMaps => {
    if (!out) out = emptyLitMaps(surfaceLayouts({ width: 1, height: 1, depth: 1 }, settings.texelSize, settings.maxTextureSize));
    if (composedVersion === version || !scene) return out;
    const { parts, terms } = relightParts()!;
    relightMaps(parts, terms, atlas, out);
    counters.relights++;
    composedVersion = version;
    return out;
  };

  return {
    setScene,
    setFade(given) {
      // The scene faded from in the same coordinates as the scene (a shaped room's enclosure).
      const next = given ? { from: encloseShapedRoom(given.from), e: given.e } : null;
      if (next) checkFade(next, scene, order);
      if (!next && !fade) return;
      fade = next;
      version++;
    },
    step,
    finish() {
      while (!progress().done) step(settings.samples, false);
    },
    get progress() {
      return progress();
    },
    maps,
    relightParts,
    get version() {
      return version;
    },
    counters,
    settings,
    releaseTargets: () => baker.dispose(),
    dispose() {
      solver.reset();
      bases.drop();
      cache.clear();
      fade = null;
      states.clear();
      order = [];
      baker.dispose();
    },
  };
}
