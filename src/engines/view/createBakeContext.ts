import type { BakeSettings } from '../bake/bakeSettings';
import { createRelightEngine, VIEWER_BAKE_SETTINGS } from '../relight/createRelightEngine';
import type { RelightEngine } from '../relight/RelightEngine';
import { watchContextLoss, type ContextWatch } from './watchContextLoss';

/**
 * The baker's own WebGL2 context (a detached canvas) and the relight engine on
 * it. Its basis maps live on the CPU, but go with the engine when the context
 * is lost: after the restore a fresh canvas (a fresh context object, so no
 * stale compiled programs are reused) gets a fresh engine, which has to
 * rebake. The engine's counters run on across engines (restores and quality
 * changes), so hosts see a rebake as more group bakes.
 */
export interface BakeContext {
  /** The engine, or null while the context is lost or when none could be made (onError said why). */
  readonly engine: RelightEngine | null;
  /** The context the engine bakes on (null while lost or when none could be made): for fences. */
  readonly gl: WebGL2RenderingContext | null;
  /** Group bakes, relights and indirect solves of every engine so far. */
  counters(): BakeCounters;
  /** A fresh engine with other settings on the same context (a quality change): it knows no scene yet. */
  setSettings(settings: Partial<BakeSettings>): RelightEngine | null;
  dispose(): void;
}

export interface BakeCounters {
  groupBakes: number;
  relightsOnly: number;
  /** Shared indirect solves (engines that count them; 0 otherwise). */
  indirectSolves: number;
}

export interface BakeContextEvents {
  onLost(): void;
  /** A fresh engine (null if it could not be made) after a restore; it knows no scene yet. */
  onRestored(engine: RelightEngine | null): void;
  onError(message: string): void;
}

/** What the context is made on: a detached canvas in the browser, a headless-gl stand-in in tests. */
export type BakeCanvas = Pick<HTMLCanvasElement, 'addEventListener' | 'removeEventListener'> & { getContext(kind: 'webgl2'): WebGL2RenderingContext | null };

export interface BakeContextOptions {
  settings?: Partial<BakeSettings>;
  /** A new canvas (default: document.createElement('canvas')). */
  canvas?: () => BakeCanvas;
}

const countersOf = (e: RelightEngine | null): BakeCounters => {
  const c = e?.counters as (RelightEngine['counters'] & { indirectSolves?: number }) | undefined;
  return { groupBakes: c?.groupBakes ?? 0, relightsOnly: c?.relightsOnly ?? 0, indirectSolves: c?.indirectSolves ?? 0 };
};

export function createBakeContext(events: BakeContextEvents, options: BakeContextOptions = {}): BakeContext {
  const newCanvas = options.canvas ?? (() => document.createElement('canvas'));
  let settings = options.settings ?? VIEWER_BAKE_SETTINGS;
  const carried: BakeCounters = { groupBakes: 0, relightsOnly: 0, indirectSolves: 0 };
  let canvas = newCanvas();
  let engine: RelightEngine | null = null;
  let gl: WebGL2RenderingContext | null = null;

  const retire = () => {
    const c = countersOf(engine);
    carried.groupBakes += c.groupBakes;
    carried.relightsOnly += c.relightsOnly;
    carried.indirectSolves += c.indirectSolves;
    engine = null;
  };

  const makeEngine = (): RelightEngine | null => {
    gl = canvas.getContext('webgl2');
    if (!gl) {
      events.onError('Could not create a WebGL2 context for baking the light.');
      return null;
    }
    try {
      return createRelightEngine(gl, settings);
    } catch (e) {
      events.onError(`The light baker cannot run on this device: ${(e as Error).message}`);
      return null;
    }
  };

  const watch = (): ContextWatch =>
    watchContextLoss(canvas as HTMLCanvasElement, {
      lost() {
        retire(); // its GPU objects are gone; the CPU basis maps go with it
        gl = null;
        events.onLost();
      },
      restored() {
        watcher.dispose();
        canvas = newCanvas();
        watcher = watch();
        engine = makeEngine();
        events.onRestored(engine);
      },
    });
  let watcher = watch();
  engine = makeEngine();

  return {
    get engine() {
      return engine;
    },
    get gl() {
      return engine ? gl : null;
    },
    counters() {
      const c = countersOf(engine);
      return { groupBakes: carried.groupBakes + c.groupBakes, relightsOnly: carried.relightsOnly + c.relightsOnly, indirectSolves: carried.indirectSolves + c.indirectSolves };
    },
    setSettings(next) {
      settings = next;
      if (watcher.lost) return null; // the restore makes the engine with the new settings
      engine?.dispose();
      retire();
      engine = makeEngine();
      return engine;
    },
    dispose() {
      engine?.dispose();
      engine = null;
      watcher.dispose();
      // Free the context now rather than when the garbage collector gets to it (browsers cap live contexts).
      canvas.getContext('webgl2')?.getExtension('WEBGL_lose_context')?.loseContext();
    },
  };
}
