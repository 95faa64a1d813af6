/**
 * Times one relight-engine bake the way the browser runs it (docs/benchmarks.md, "3D lifecycle"):
 * `setScene`, then `step()` until every group shows light (`progress.lit`: the first lit frame's
 * bake work), then `finish()` (the rest of the indirect work, no previews). Wall clock from
 * setScene, on a context the caller made: a fresh context measures a first toggle, compilation
 * included.
 */
import type { BakeScene } from '../../src/engines/bake/bakeScene';
import type { BakeSettings } from '../../src/engines/bake/bakeSettings';
import { createRelightEngine } from '../../src/engines/relight/createRelightEngine';

export interface EngineBakeTiming {
  /** setScene → every group lit (direct light of every module), ms. */
  litMs: number;
  /** setScene → finish() returned and maps() composed, ms. */
  doneMs: number;
  /** Groups the engine baked (its own counter). */
  groupBakes: number;
}

export function timeEngineBake(gl: WebGL2RenderingContext, scene: BakeScene, settings?: Partial<BakeSettings>): EngineBakeTiming {
  const engine = settings ? createRelightEngine(gl, settings) : createRelightEngine(gl);
  try {
    const t0 = performance.now();
    engine.setScene(scene);
    let guard = 0;
    while (!engine.progress.lit) {
      engine.step(undefined, false);
      if (++guard > 100_000) throw new Error('the engine never reported lit');
    }
    engine.maps();
    const litMs = performance.now() - t0;
    engine.finish();
    engine.maps();
    const doneMs = performance.now() - t0;
    return { litMs, doneMs, groupBakes: engine.counters.groupBakes };
  } finally {
    engine.dispose();
  }
}
