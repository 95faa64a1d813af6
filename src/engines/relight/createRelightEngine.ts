import type { BakeScene } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import { resolveBakeSettings } from '../bake/bakeSettings';
import { createBaker, type BakeJob } from '../bake/createBaker';
import { surfaceLayouts } from '../bake/surfaceLayout';
import { SURFACE_NAMES, type Rgb } from '../../core/model/lightingScene';
import { groupLuminaires, groupWeight, roomKey, type LuminaireGroup } from './luminaireGroups';
import { objectsKey } from './objectsKey';
import { emptyLitMaps, relightMaps, type BasisMaps, type LitMaps } from './relightMaps';

/**
 * Quality of the viewer's basis bakes: coarser texels than the CLI default, as
 * each module gets its own bake. 128 samples (not 64): on the corner-l
 * configuration the RMS error of the indirect light averaged over 25 cm
 * patches (the visible blotches) drops from 2.0 % to 1.4 % of a 1024-sample
 * reference, for 1.6× the bake time; a wider blur (8–10 texels) was cheaper
 * but measured worse (2.2–2.8 %: it flattens real gradients near corners and
 * lamps). docs/viewer.md, "Viewer bake quality".
 */
export const VIEWER_BAKE_SETTINGS: Partial<BakeSettings> = { texelSize: 0.05, maxTextureSize: 256, samples: 128, bounces: 3, samplesPerDraw: 8, blurRadius: 5 };

/** Least time between two previews of a bake under way (each costs a finalize and a read-back). */
export const PREVIEW_MS = 300;

export interface EngineProgress {
  /** Groups whose basis is final. */
  groupsDone: number;
  groups: number;
  /** 0..1 over all pending indirect work. */
  fraction: number;
  /** Every group's basis is final. */
  done: boolean;
  /** Every group has at least its direct-only basis: the image shows all the light. */
  lit: boolean;
}

export interface EngineCounters {
  /** Groups baked (a new or moved group counts once), since the engine was made. */
  groupBakes: number;
  /** Scene updates that needed no bake at all (dimming, colour, on/off only). */
  relightsOnly: number;
  /** Weighted sums computed. */
  relights: number;
}

export interface SetSceneResult {
  /** Groups that will be (re)baked. */
  bake: number;
  /** Groups whose basis was kept. */
  reused: number;
}

interface GroupState {
  group: LuminaireGroup;
  basis: BasisMaps | null;
  final: boolean;
}

/**
 * Bakes each luminaire group of a scene into basis maps (once), then relights
 * by weighted sums: a scene change that only touches dimming or colour costs a
 * relight; a moved or added luminaire bakes only its group; a room change
 * bakes everything. Bakes are progressive: `step` advances the one bake under
 * way by a few samples (callers slice it over frames), and every group first
 * gets its direct-only basis, so light appears at once and refines.
 */
export interface RelightEngine {
  setScene(scene: BakeScene): SetSceneResult;
  /**
   * Advance pending bakes by up to `samples` indirect samples per texel; returns the progress.
   * With `preview` (default) the partial solution is read back at most every PREVIEW_MS.
   */
  step(samples?: number, preview?: boolean): EngineProgress;
  /** Finish every pending bake now (for the CLI and tests). */
  finish(): void;
  readonly progress: EngineProgress;
  /** The relit maps for the current scene's weights (recomputed only when something changed). */
  maps(): LitMaps;
  /** Monotonic: bumps whenever `maps()` would return new values. */
  readonly version: number;
  readonly counters: EngineCounters;
  readonly settings: BakeSettings;
  dispose(): void;
}

export function createRelightEngine(gl: WebGL2RenderingContext, partial: Partial<BakeSettings> = VIEWER_BAKE_SETTINGS): RelightEngine {
  const settings = resolveBakeSettings(partial);
  const baker = createBaker(gl);
  let scene: BakeScene | null = null;
  let room = '';
  let states = new Map<string, GroupState>();
  let order: GroupState[] = [];
  let job: { state: GroupState; job: BakeJob; lastPreview: number } | null = null;
  let out: LitMaps | null = null;
  let version = 0;
  let composedVersion = -1;
  const counters: EngineCounters = { groupBakes: 0, relightsOnly: 0, relights: 0 };
  const totalWork = () => Math.max(1, settings.bounces) * settings.samples;

  const readBasis = (j: BakeJob): BasisMaps => {
    const m = j.readMaps();
    const basis = Object.fromEntries(SURFACE_NAMES.map((n) => [n, { direct: m[n].direct, total: m[n].total }])) as BasisMaps;
    if (m.objects) basis.objects = { atlas: m.objects.atlas, direct: m.objects.direct, total: m.objects.total };
    return basis;
  };

  // Direct-only bases for every new group first (one group per call, so a caller slicing the
  // work over frames stays responsive): light shows up before any indirect work.
  const bakeDirectOnly = (): boolean => {
    const st = order.find((s) => !s.basis);
    if (!st) return false;
    counters.groupBakes++;
    const j = baker.start(groupScene(scene!, st.group), settings);
    try {
      j.finalize();
      st.basis = readBasis(j);
    } finally {
      j.dispose();
    }
    version++;
    return true;
  };

  const progress = (): EngineProgress => {
    const done = order.filter((s) => s.final).length;
    // Direct-only previews count as a small first share of each group's work.
    const previews = order.filter((s) => s.basis && !s.final).length;
    let fraction = order.length === 0 ? 1 : (done + 0.05 * previews) / order.length;
    if (job && order.length > 0) {
      const p = job.job.progress;
      const within = p.done ? 1 : (p.bounce * settings.samples + p.samplesDone) / totalWork();
      fraction += (0.95 * within) / order.length;
    }
    return { groupsDone: done, groups: order.length, fraction: Math.min(1, fraction), done: done === order.length, lit: order.every((s) => s.basis) };
  };

  const finishJob = () => {
    if (!job) return;
    job.state.basis = readBasis(job.job);
    job.state.final = true;
    job.job.dispose();
    job = null;
    version++;
  };

  const step = (samples = settings.samplesPerDraw, preview = true): EngineProgress => {
    if (!scene || bakeDirectOnly()) return progress();
    if (!job) {
      const next = order.find((s) => !s.final);
      if (!next) return progress();
      job = { state: next, job: baker.start(groupScene(scene, next.group), settings), lastPreview: performance.now() };
    }
    const p = job.job.step(samples);
    if (p.done) finishJob();
    else if (preview && performance.now() - job.lastPreview > PREVIEW_MS) {
      // A preview of the partial indirect solution a few times a second: the image converges while the user looks.
      job.state.basis = readBasis(job.job);
      job.lastPreview = performance.now();
      version++;
    }
    return progress();
  };

  const engine: RelightEngine = {
    setScene(next) {
      // Objects are part of the room: moving, adding or removing one is a new scene and rebakes every group.
      const nextRoom = roomKey(next.room) + objectsKey(next.objects);
      if (nextRoom !== room) {
        job?.job.dispose();
        job = null;
        states = new Map();
        room = nextRoom;
        const layouts = surfaceLayouts(next.room, settings.texelSize, settings.maxTextureSize);
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
          kept.set(g.key, { group: g, basis: null, final: false });
          bake++;
        }
      }
      if (job && !kept.has(job.state.group.key)) {
        job.job.dispose();
        job = null;
      } else if (job) job.state = kept.get(job.state.group.key)!;
      states = kept;
      order = groups.map((g) => kept.get(g.key)!);
      if (bake === 0) counters.relightsOnly++;
      version++;
      return { bake, reused: groups.length - bake };
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
      const lums = scene.luminaires;
      const parts = order.filter((s) => s.basis).map((s) => ({ basis: s.basis!, weight: groupWeight(s.group, lums) as Rgb }));
      relightMaps(parts, out);
      counters.relights++;
      composedVersion = version;
      return out;
    },
    get version() {
      return version;
    },
    counters,
    settings,
    dispose() {
      job?.job.dispose();
      job = null;
      states.clear();
      order = [];
      baker.dispose();
    },
  };
  return engine;
}

/** One group's basis scene: the room, the group's luminaires at unit weight, and the scene's objects (they shade and bounce every group's light). */
function groupScene(scene: BakeScene, group: LuminaireGroup): BakeScene {
  return { room: scene.room, luminaires: group.basis, ...(scene.objects && scene.objects.length > 0 ? { objects: scene.objects } : {}) };
}
