import { reflectanceRgb } from '../bake/bakeScene';
import type { BakeSettings } from '../bake/bakeSettings';
import { resolveBakeSettings } from '../bake/bakeSettings';
import { createBaker, type Baker } from '../bake/createBaker';
import { encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import { composeMaps, relightPartsOf } from './composeRelight';
import { createDaylightBasisCache, DAYLIGHT_BASIS_CACHE_BYTES } from './daylightBasisCache';
import { LIGHT_SOURCES } from './daylightGroups';
import { createDirectBasisQueue, type DirectBasisQueue } from './directBasisQueue';
import { progressOf, stepEngine } from './engineSolve';
import { targetKey } from './engineWeights';
import { createIndirectSolver } from './indirectSolver';
import { reflectedFlux } from './reflectedFlux';
import type { RelightEngineState } from './relightEngineState';
import type { RelightEngine } from './RelightEngine';
import { checkFade, setEngineScene } from './setEngineScene';
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

/**
 * The direct basis queue of an engine: a basis is the direct pass alone (with no bounces the baker
 * skips the bright patches, the gather and the flux record); its lamps are uniforms, so a moved
 * module, or another of the same type, reuses the compiled programs. Each basis read back gets
 * its reflected direct flux (the Φ-scaling between solves) and bumps the version.
 */
function basisQueue(baker: Baker, settings: BakeSettings, engine: () => RelightEngineState): DirectBasisQueue {
  return createDirectBasisQueue(
    baker,
    { ...settings, bounces: 0, lampUniforms: true },
    (group) => (group.daylight ? engine().counters.daylightBakes++ : engine().counters.groupBakes++),
    (s, d) => {
      const st = engine();
      st.atlas = d.objects?.atlas ?? null;
      const flux = reflectedFlux(d.surfaces, st.layouts, reflectanceRgb(st.scene!.room), st.atlas, d.objects?.emitted ?? null);
      s.basis = { ...d, flux, luminaires: s.group.basis };
      st.version++;
    },
  );
}

/** Frees every basis, solve and target of the engine. */
function disposeEngine(st: RelightEngineState): void {
  st.solver.reset();
  st.bases.drop();
  st.cache.clear();
  st.daylightCache.clear();
  st.fade = null;
  st.states.clear();
  st.order = [];
  st.baker.dispose();
}

/** Options of createRelightEngine. */
export interface RelightEngineOptions {
  /** Bytes the daylight bases kept out of the scene may hold (daylightBasisCache.ts); default DAYLIGHT_BASIS_CACHE_BYTES, 16 MiB. */
  daylightCacheBytes?: number;
}

/**
 * The relight engine (RelightEngine.ts): the groups of the current scene (luminaire groups and
 * the daylight's sky and sun, daylightGroups.ts) and their bases (directBasisQueue.ts bakes them),
 * the shared indirect solve (engineSolve.ts, indirectSolver.ts; solutionCache.ts keeps the
 * finished ones) and the relit maps composed from them on demand (composeRelight.ts).
 */
export function createRelightEngine(gl: WebGL2RenderingContext, partial: Partial<BakeSettings> = VIEWER_BAKE_SETTINGS, options: RelightEngineOptions = {}): RelightEngine {
  const settings = resolveBakeSettings(partial);
  const cache = createSolutionCache();
  const baker = createBaker(gl);
  const st: RelightEngineState = {
    settings,
    baker,
    cache,
    solver: createIndirectSolver(cache, settings),
    bases: basisQueue(baker, settings, () => st),
    daylightCache: createDaylightBasisCache(options.daylightCacheBytes ?? DAYLIGHT_BASIS_CACHE_BYTES),
    counters: { groupBakes: 0, daylightBakes: 0, relightsOnly: 0, relights: 0, indirectSolves: 0 },
    given: null,
    scene: null,
    room: '',
    layouts: [],
    atlas: null,
    states: new Map(),
    order: [],
    fade: null,
    sources: 'both',
    out: null,
    version: 0,
    composedVersion: -1,
  };
  return {
    setScene: (given) => setEngineScene(st, given),
    setFade(given) {
      // The scene faded from in the same coordinates as the scene (a shaped room's enclosure).
      const next = given ? { from: encloseShapedRoom(given.from), e: given.e } : null;
      if (next) checkFade(st, next);
      if (!next && !st.fade) return;
      st.fade = next;
      st.version++;
    },
    setLightSources(sources) {
      if (!LIGHT_SOURCES.includes(sources)) throw new Error(`setLightSources: '${String(sources)}' is not one of ${LIGHT_SOURCES.join(', ')}`);
      if (sources === st.sources) return;
      const factorChanges = (sources === 'daylight-factor') !== (st.sources === 'daylight-factor');
      st.sources = sources;
      // The daylight factor's overcast basis joins or leaves the groups: the scene again (no other basis changes).
      if (factorChanges && st.given) {
        setEngineScene(st, st.given);
        return;
      }
      // The solve under way is for the weights shown before; the cached solves of each choice stay.
      st.solver.dropUnless(targetKey(st));
      st.version++;
    },
    get lightSources() {
      return st.sources;
    },
    step: (samples = settings.samplesPerDraw, preview = true) => stepEngine(st, samples, preview),
    finish() {
      while (!progressOf(st).done) stepEngine(st, settings.samples, false);
    },
    get progress() {
      return progressOf(st);
    },
    maps: () => composeMaps(st),
    relightParts: () => relightPartsOf(st),
    get version() {
      return st.version;
    },
    counters: st.counters,
    daylightCache: st.daylightCache,
    settings,
    releaseTargets: () => st.baker.dispose(),
    dispose: () => disposeEngine(st),
  };
}
