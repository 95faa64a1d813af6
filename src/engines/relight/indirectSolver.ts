import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakeSettings } from '../bake/bakeSettings';
import type { BakeJob } from '../bake/createBaker';
import type { IndirectSolution } from './relightMaps';
import type { SolutionCache } from './solutionCache';

/** Least time between two previews of the first solve under way (each costs a finalize and a read-back). */
export const PREVIEW_MS = 300;

/** A shared indirect solve just started: the baker's job and the reflected direct flux Φ of the weights it solves. */
export interface StartedSolve {
  job: BakeJob;
  flux: Rgb;
}

interface SolveJob extends StartedSolve {
  key: string;
  lastPreview: number;
}

/**
 * Schedules the shared indirect solve (docs/viewer.md, "Relighting without rebaking"): one job at
 * a time, toward the scene's own weights key; a job for weights no longer wanted is dropped; a
 * finished solve goes to the solution cache. `latest` is the solution on screen meanwhile.
 */
export interface IndirectSolver {
  /** The last finished solve, or a preview of the first solve of a room; null before any. */
  readonly latest: IndirectSolution | null;
  /** 0..1: how far the solve under way is (0 when none is). */
  fraction(): number;
  /**
   * Advances the solve at `key` by up to `samples` samples per texel, starting it (with `start`)
   * when none is under way for that key. Returns whether a solution was read back (`latest` changed).
   */
  advance(key: string, start: () => StartedSolve, samples: number, preview: boolean): boolean;
  /** Drops a solve under way for weights other than `key` (the one shown stays until a new one is done). */
  dropUnless(key: string): void;
  /** Drops the solve under way and forgets `latest` (a new room, or the engine disposed). */
  reset(): void;
}

function readSolution(s: SolveJob, final: boolean): IndirectSolution {
  const m = s.job.readMaps();
  const surfaces = Object.fromEntries(SURFACE_NAMES.map((name) => [name, m[name].indirect])) as Record<SurfaceName, Float32Array>;
  return { surfaces, ...(m.objects ? { objects: m.objects.indirect } : {}), flux: s.flux, key: s.key, final };
}

/** A solver whose finished solutions go to `cache`; `settings` gives the samples and bounces a solve takes. */
export function createIndirectSolver(cache: SolutionCache, settings: BakeSettings): IndirectSolver {
  let solve: SolveJob | null = null;
  let latest: IndirectSolution | null = null;
  const drop = () => {
    solve?.job.dispose();
    solve = null;
  };
  return {
    get latest() {
      return latest;
    },
    fraction() {
      if (!solve) return 0;
      const p = solve.job.progress;
      return p.done ? 1 : (p.bounce * settings.samples + p.samplesDone) / (Math.max(1, settings.bounces) * settings.samples);
    },
    advance(key, start, samples, preview) {
      if (solve && solve.key !== key) drop();
      if (!solve) solve = { ...start(), key, lastPreview: performance.now() };
      const p = solve.job.step(samples);
      if (p.done) {
        latest = readSolution(solve, true);
        cache.remember(latest);
        drop();
        return true;
      }
      if (preview && !latest?.final && performance.now() - solve.lastPreview > PREVIEW_MS) {
        // The first solve of a room: nothing better is on screen, so its partial solution is shown a few times a second.
        latest = readSolution(solve, false);
        solve.lastPreview = performance.now();
        return true;
      }
      return false;
    },
    dropUnless(key) {
      if (solve && solve.key !== key) drop();
    },
    reset() {
      drop();
      latest = null;
    },
  };
}
