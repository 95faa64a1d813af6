import { createRelightEngine, type RelightEngine } from '../relight/createRelightEngine';
import { watchContextLoss, type ContextWatch } from './watchContextLoss';

/**
 * The baker's own WebGL2 context (a detached canvas) and the relight engine on
 * it. Its basis maps live on the CPU, but go with the engine when the context
 * is lost: after the restore a fresh canvas (a fresh context object, so no
 * stale compiled programs are reused) gets a fresh engine, which has to
 * rebake. The engine's counters run on across engines, so hosts see the
 * rebake as more group bakes.
 */
export interface BakeContext {
  /** The engine, or null while the context is lost or when none could be made (onError said why). */
  readonly engine: RelightEngine | null;
  /** Group bakes and relights of every engine so far. */
  counters(): { groupBakes: number; relightsOnly: number };
  dispose(): void;
}

export interface BakeContextEvents {
  onLost(): void;
  /** A fresh engine (null if it could not be made) after a restore; it knows no scene yet. */
  onRestored(engine: RelightEngine | null): void;
  onError(message: string): void;
}

export function createBakeContext(events: BakeContextEvents): BakeContext {
  const carried = { groupBakes: 0, relightsOnly: 0 };
  let canvas = document.createElement('canvas');
  let engine: RelightEngine | null = null;

  const makeEngine = (): RelightEngine | null => {
    const gl = canvas.getContext('webgl2');
    if (!gl) {
      events.onError('Could not create a WebGL2 context for baking the light.');
      return null;
    }
    try {
      return createRelightEngine(gl);
    } catch (e) {
      events.onError(`The light baker cannot run on this device: ${(e as Error).message}`);
      return null;
    }
  };

  const watch = (): ContextWatch =>
    watchContextLoss(canvas, {
      lost() {
        if (engine) {
          carried.groupBakes += engine.counters.groupBakes;
          carried.relightsOnly += engine.counters.relightsOnly;
        }
        engine = null; // its GPU objects are gone; the CPU basis maps go with it
        events.onLost();
      },
      restored() {
        watcher.dispose();
        canvas = document.createElement('canvas');
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
    counters: () => ({ groupBakes: carried.groupBakes + (engine?.counters.groupBakes ?? 0), relightsOnly: carried.relightsOnly + (engine?.counters.relightsOnly ?? 0) }),
    dispose() {
      engine?.dispose();
      watcher.dispose();
      // Free the context now rather than when the garbage collector gets to it (browsers cap live contexts).
      canvas.getContext('webgl2')?.getExtension('WEBGL_lose_context')?.loseContext();
    },
  };
}
