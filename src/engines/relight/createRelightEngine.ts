import { reflectanceRgb, type BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import { resolveBakeSettings } from '../bake/bakeSettings';
import { createBaker, type BakeJob } from '../bake/createBaker';
import { surfaceLayouts, type SurfaceLayout } from '../bake/surfaceLayout';
import type { ObjectAtlas } from '../bake/objects/preparedObjects';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { groupLuminaires, groupWeight, roomKey, type LuminaireGroup } from './luminaireGroups';
import { objectsKey } from './objectsKey';
import { indirectScale, reflectedFlux, weightedFlux } from './reflectedFlux';
import { emptyLitMaps, relightMaps, sumDirect, type DirectBasis, type IndirectSolution, type IndirectTerm, type LitMaps, type WeightedBasis } from './relightMaps';

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

/** Least time between two previews of the first solve under way (each costs a finalize and a read-back). */
export const PREVIEW_MS = 300;

export interface EngineProgress {
  /** Groups whose direct basis is baked. */
  groupsDone: number;
  groups: number;
  /** 0..1 over the pending work: the direct bases (a small first share), then the shared indirect solve. */
  fraction: number;
  /** Every group's direct basis is baked and the indirect light is solved at the current weights. */
  done: boolean;
  /** Every group has its direct basis: the image shows all the direct light. */
  lit: boolean;
  /** The indirect light shown is the finished solve at the current weights (not a preview, not a scaled earlier solve). */
  exact: boolean;
}

export interface EngineCounters {
  /** Direct bases baked (a new or moved group counts once), since the engine was made. */
  groupBakes: number;
  /** Scene updates that needed no group bake (dimming, colour, on/off, removed groups only). */
  relightsOnly: number;
  /** Weighted sums computed. */
  relights: number;
  /** Shared indirect solves started (the first of a room and every re-solve after a change of weights or groups). */
  indirectSolves: number;
}

export interface SetSceneResult {
  /** Groups whose direct basis will be (re)baked. */
  bake: number;
  /** Groups whose basis was kept. */
  reused: number;
}

interface GroupState {
  group: LuminaireGroup;
  basis: DirectBasis | null;
}

interface SolveJob {
  job: BakeJob;
  key: string;
  flux: Rgb;
  lastPreview: number;
}

/**
 * Finished indirect solutions kept, by weights key (least recently used dropped first): a recalled
 * light scene whose weights were solved before is exact at once, and a crossfade between two solved
 * scenes blends their solutions. One solution is the room's indirect maps (about 0.5 MB for a
 * 5 × 4 m room at the viewer's 5 cm texels, plus the objects' atlas), so 8 stay well under 20 MB.
 */
export const SOLUTION_CACHE_SIZE = 8;

/** A crossfade shown by the engine: weights (1 − e)·w_from + e·w_scene per group (docs/light-scenes.md). */
export interface EngineFade {
  /** The scene faded from: the same luminaires (geometry) as the current scene, other dimming and colour. */
  from: BakeScene;
  /** Fade fraction in [0, 1] (already eased): 0 shows `from`, 1 the scene. */
  e: number;
}

/** Share of the progress fraction taken by the direct bases (cheap: no bounces), the rest is the shared solve. */
const DIRECT_SHARE = 0.1;

/**
 * Relighting by one shared indirect solve (docs/viewer.md, "Relighting without rebaking"). Each
 * luminaire group gets a direct basis only (direct maps at unit weight, no bounces); the
 * indirect light of the whole scene is one solve from Σ_g w_g · direct_g (the gather reads only
 * the direct maps, and it is linear in them). A change of dimming or colour, or an added, moved
 * or removed group, shows the exact direct light at once and the last solve's indirect light
 * scaled per channel by Φ_now/Φ_solve (reflected direct flux, reflectedFlux.ts) until a
 * background re-solve at the new weights is done; a room or objects change rebakes every basis.
 * Work is progressive: `step` bakes one missing basis per call, then advances the solve by a
 * few samples (callers slice it over frames).
 */
export interface RelightEngine {
  setScene(scene: BakeScene): SetSceneResult;
  /**
   * Show a crossfade from `fade.from` to the current scene at fraction `fade.e`, or null for the scene
   * itself: a relight, never a bake. The direct light is Σ_g ((1 − e)·w_from + e·w_scene)_g · direct_g;
   * the indirect light is (1 − e)·I_from + e·I_scene exactly when both weights were solved (the
   * solution cache), otherwise the last solve scaled by Φ. Only the scene's own weights (the end of
   * the fade) are ever solved. Throws when `from` has other luminaires than the scene.
   */
  setFade(fade: EngineFade | null): void;
  /**
   * Advance pending work by one direct basis or up to `samples` indirect samples per texel; returns the progress.
   * With `preview` (default) the first solve of a room is read back and shown at most every PREVIEW_MS
   * (a re-solve keeps showing the previous solution, scaled, until it is done).
   */
  step(samples?: number, preview?: boolean): EngineProgress;
  /** Finish every pending bake and the solve now (for the CLI and tests). */
  finish(): void;
  readonly progress: EngineProgress;
  /** The relit maps for the current scene's weights (recomputed only when something changed). */
  maps(): LitMaps;
  /** Monotonic: bumps whenever `maps()` would return new values. */
  readonly version: number;
  readonly counters: EngineCounters;
  readonly settings: BakeSettings;
  /**
   * Free the baker's pooled render targets (kept only to speed up the next bake; jobs under way
   * keep theirs): the bake service calls it on low-memory devices once the bake is done. The
   * bases and maps stay; the next bake allocates targets anew.
   */
  releaseTargets(): void;
  dispose(): void;
}

export function createRelightEngine(gl: WebGL2RenderingContext, partial: Partial<BakeSettings> = VIEWER_BAKE_SETTINGS): RelightEngine {
  const settings = resolveBakeSettings(partial);
  // A basis is the direct pass alone: with no bounces the baker skips the bright patches, the gather and the flux record.
  // Its lamps are uniforms: a moved module, or another of the same type, reuses the compiled programs.
  const basisSettings: BakeSettings = { ...settings, bounces: 0, lampUniforms: true };
  const baker = createBaker(gl);
  let scene: BakeScene | null = null;
  let room = '';
  let layouts: SurfaceLayout[] = [];
  let atlas: ObjectAtlas | null = null;
  let states = new Map<string, GroupState>();
  let order: GroupState[] = [];
  let solve: SolveJob | null = null;
  let solved: IndirectSolution | null = null;
  /** Finished solutions by weights key, oldest use first (SOLUTION_CACHE_SIZE). */
  let finals = new Map<string, IndirectSolution>();
  let fade: EngineFade | null = null;
  let out: LitMaps | null = null;
  let version = 0;
  let composedVersion = -1;
  const counters: EngineCounters = { groupBakes: 0, relightsOnly: 0, relights: 0, indirectSolves: 0 };

  /** A group's weight in the scene itself (the end of a fade). */
  const ownWeight = (s: GroupState) => groupWeight(s.group, scene!.luminaires);
  const fromWeight = (s: GroupState) => groupWeight(s.group, fade!.from.luminaires);
  /** The weight shown: the scene's, or during a fade (1 − e)·from + e·scene per channel. */
  const weightOf = (s: GroupState): Rgb => {
    const w = ownWeight(s);
    if (!fade) return w;
    const a = fromWeight(s);
    const e = fade.e;
    return [(1 - e) * a[0] + e * w[0], (1 - e) * a[1] + e * w[1], (1 - e) * a[2] + e * w[2]];
  };
  /** The groups that are shown (basis baked) with the given weights. */
  const partsAt = (weight: (s: GroupState) => Rgb): WeightedBasis[] => order.filter((s) => s.basis).map((s) => ({ basis: s.basis!, weight: weight(s) }));
  const parts = (): WeightedBasis[] => partsAt(weightOf);
  /** The weights the indirect light depends on: every lit group with its RGB weight (order-free; '' = no light at all). */
  const keyAt = (weight: (s: GroupState) => Rgb): string =>
    order
      .map((s) => [s.group.key, weight(s)] as const)
      .filter(([, w]) => w.some((v) => v > 0))
      .map(([k, w]) => `${k}=${w.join(',')}`)
      .sort()
      .join('|');
  /** The key of what is shown, and of the scene itself (what a solve works toward). */
  const weightsKey = (): string => keyAt(weightOf);
  const targetKey = (): string => keyAt(ownWeight);
  /** No light (key '') has exactly no indirect light: nothing to solve. */
  const isExact = (key: string) => key === '' || finals.has(key);
  /** A finished solution at `key`, marked as the latest used (least-recently-used order); null for no light. */
  const finalAt = (key: string): IndirectSolution | null | undefined => {
    if (key === '') return null;
    const sol = finals.get(key);
    if (sol) {
      finals.delete(key);
      finals.set(key, sol);
    }
    return sol;
  };
  const remember = (sol: IndirectSolution) => {
    finals.delete(sol.key);
    finals.set(sol.key, sol);
    while (finals.size > SOLUTION_CACHE_SIZE) finals.delete(finals.keys().next().value!);
  };
  /** The group keys of a luminaire list, in order: a fade's two scenes must have the same. */
  const groupKeys = (sc: BakeScene) => groupLuminaires(sc.luminaires).map((g) => g.key).join('|');

  /**
   * A direct basis whose passes are issued but not read back yet. A basis takes two steps: the
   * first issues the GPU work (draws return at once: in a browser the GPU process runs them), the
   * second reads the maps back. The caller's slicer fences between steps (createBakeSlicer), so
   * the read-back finds the work done instead of blocking the page while a software GPU runs a
   * furnished room's shadowed direct passes (seconds on SwiftShader).
   */
  let pendingBasis: { key: string; job: BakeJob } | null = null;
  const dropPendingBasis = () => {
    pendingBasis?.job.dispose();
    pendingBasis = null;
  };

  // Direct bases for every new group first, one group per two calls (issue, then read back), so a caller slicing the work stays responsive.
  const bakeDirectBasis = (): boolean => {
    if (pendingBasis) {
      const { key, job } = pendingBasis;
      pendingBasis = null;
      try {
        const st = states.get(key);
        if (st && !st.basis) {
          const d = job.readDirect();
          atlas = d.objects?.atlas ?? null;
          const flux = reflectedFlux(d.surfaces, layouts, reflectanceRgb(scene!.room), atlas, d.objects?.emitted ?? null);
          st.basis = { ...d, flux };
          version++;
        }
      } finally {
        job.dispose();
      }
      return true;
    }
    const st = order.find((s) => !s.basis);
    if (!st) return false;
    counters.groupBakes++;
    const job = baker.start(groupScene(scene!, st.group), basisSettings);
    try {
      // Everything up to the read-back (objects: chart dilation of the atlas) is issued now.
      job.finalize();
    } catch (error) {
      job.dispose();
      throw error;
    }
    pendingBasis = { key: st.group.key, job };
    return true;
  };

  const progress = (): EngineProgress => {
    const n = order.length;
    const based = order.filter((s) => s.basis).length;
    const lit = based === n;
    // The pending work is the scene's own solve; during a fade the image is exact when both ends are solved.
    const done = lit && isExact(targetKey());
    const exact = done && (!fade || isExact(keyAt(fromWeight)));
    let solveFraction = done ? 1 : 0;
    if (!done && solve) {
      const p = solve.job.progress;
      solveFraction = p.done ? 1 : (p.bounce * settings.samples + p.samplesDone) / (Math.max(1, settings.bounces) * settings.samples);
    }
    const fraction = n === 0 ? 1 : DIRECT_SHARE * (based / n) + (1 - DIRECT_SHARE) * solveFraction;
    return { groupsDone: based, groups: n, fraction: Math.min(1, fraction), done, lit, exact };
  };

  const readSolution = (s: SolveJob, final: boolean): IndirectSolution => {
    const m = s.job.readMaps();
    const surfaces = Object.fromEntries(SURFACE_NAMES.map((name) => [name, m[name].indirect])) as Record<SurfaceName, Float32Array>;
    return { surfaces, ...(m.objects ? { objects: m.objects.indirect } : {}), flux: s.flux, key: s.key, final };
  };

  const startSolve = (key: string): SolveJob => {
    // The scene's own weights: a fade's intermediate weights are never solved (the blend of the ends is exact).
    const weighted = partsAt(ownWeight);
    const direct = sumDirect(weighted, layouts, atlas);
    const objects = scene!.objects && scene!.objects.length > 0 && direct.objects ? { objects: scene!.objects, direct: direct.objects } : undefined;
    counters.indirectSolves++;
    const job = baker.startFromDirect(scene!.room, direct.surfaces, settings, objects);
    const flux = weightedFlux(weighted.map((p) => ({ flux: p.basis.flux, weight: p.weight })));
    return { job, key, flux, lastPreview: performance.now() };
  };

  const dropSolve = () => {
    solve?.job.dispose();
    solve = null;
  };

  const step = (samples = settings.samplesPerDraw, preview = true): EngineProgress => {
    if (!scene || bakeDirectBasis()) return progress();
    const key = targetKey();
    if (isExact(key)) return progress();
    if (solve && solve.key !== key) dropSolve();
    if (!solve) solve = startSolve(key);
    const p = solve.job.step(samples);
    if (p.done) {
      solved = readSolution(solve, true);
      remember(solved);
      dropSolve();
      version++;
    } else if (preview && !solved?.final && performance.now() - solve.lastPreview > PREVIEW_MS) {
      // The first solve of a room: nothing better is on screen, so its partial solution is shown a few times a second.
      solved = readSolution(solve, false);
      solve.lastPreview = performance.now();
      version++;
    }
    return progress();
  };

  const engine: RelightEngine = {
    setScene(next) {
      // Objects are part of the room: moving, adding or removing one is a new scene and rebakes every group.
      const nextRoom = roomKey(next.room) + objectsKey(next.objects);
      if (nextRoom !== room) {
        dropSolve();
        dropPendingBasis();
        solved = null;
        finals = new Map();
        atlas = null;
        states = new Map();
        room = nextRoom;
        layouts = surfaceLayouts(next.room, settings.texelSize, settings.maxTextureSize);
        out = emptyLitMaps(layouts);
      }
      scene = next;
      const groups = groupLuminaires(next.luminaires);
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
      states = kept;
      order = groups.map((g) => kept.get(g.key)!);
      // A basis under way for a group that is gone (moved, removed) is of no use.
      if (pendingBasis && !kept.has(pendingBasis.key)) dropPendingBasis();
      // A fade from a scene with other luminaires (a module added or moved meanwhile) cannot be shown: the scene is.
      if (fade && groupKeys(fade.from) !== groups.map((g) => g.key).join('|')) fade = null;
      // A solve under way for other weights is of no use any more (the shown one stays until the new solve is done).
      if (solve && solve.key !== targetKey()) dropSolve();
      if (bake === 0) counters.relightsOnly++;
      version++;
      return { bake, reused: groups.length - bake };
    },
    setFade(next) {
      if (next) {
        if (!(next.e >= 0 && next.e <= 1)) throw new Error(`setFade: fraction ${next.e} is outside [0, 1]`);
        if (!scene) throw new Error('setFade: no scene to fade to');
        if (groupKeys(next.from) !== order.map((s) => s.group.key).join('|')) throw new Error('setFade: the scene faded from has other luminaires than the scene');
      }
      if (!next && !fade) return;
      fade = next ? { from: next.from, e: next.e } : null;
      version++;
    },
    step,
    finish() {
      while (!progress().done) step(settings.samples, false);
    },
    get progress() {
      return progress();
    },
    maps() {
      if (!out) out = emptyLitMaps(surfaceLayouts({ width: 1, height: 1, depth: 1 }, settings.texelSize, settings.maxTextureSize));
      if (composedVersion === version || !scene) return out;
      const weighted = parts();
      const key = weightsKey();
      let terms: IndirectTerm[] = [];
      if (key !== '') {
        // A fade between two solved weightings: the indirect light is linear in the weights, so the blend is exact.
        const ends = fade ? [finalAt(keyAt(fromWeight)), finalAt(targetKey())] : null;
        const e = fade?.e ?? 1;
        if (ends && ends[0] !== undefined && ends[1] !== undefined) {
          const [a, b] = ends;
          terms = [...(a ? [{ solution: a, scale: [1 - e, 1 - e, 1 - e] as Rgb }] : []), ...(b ? [{ solution: b, scale: [e, e, e] as Rgb }] : [])];
        } else {
          const exact = finalAt(key) ?? (solved?.key === key ? solved : null);
          // Solved at these weights (final or a preview of the first solve): as is; otherwise the last solve scaled by the reflected direct flux.
          if (exact) terms = [{ solution: exact, scale: [1, 1, 1] }];
          else if (solved) terms = [{ solution: solved, scale: indirectScale(weightedFlux(weighted.map((p) => ({ flux: p.basis.flux, weight: p.weight }))), solved.flux) }];
        }
      }
      relightMaps(weighted, terms, atlas, out);
      counters.relights++;
      composedVersion = version;
      return out;
    },
    get version() {
      return version;
    },
    counters,
    settings,
    releaseTargets: () => baker.dispose(),
    dispose() {
      dropSolve();
      dropPendingBasis();
      solved = null;
      finals.clear();
      fade = null;
      states.clear();
      order = [];
      baker.dispose();
    },
  };
  return engine;
}

/** One group's basis scene: the room, the group's luminaires at unit weight, and the scene's objects (they shade every group's light). */
function groupScene(scene: BakeScene, group: LuminaireGroup): BakeScene {
  return { room: scene.room, luminaires: group.basis, ...(scene.objects && scene.objects.length > 0 ? { objects: scene.objects } : {}) };
}
