/**
 * Light-scene crossfades in the relight engine (docs/light-scenes.md, "3D crossfade"): the map at
 * fade fraction e is (1 − e)·A + e·B of the two scenes' relit maps (direct and total, walls and
 * objects' atlas: light is linear in the weights and both indirect solutions are kept), a fade is
 * a relight only (no group bake, no indirect solve), a recalled solved scene is exact at once, and
 * a fade to a new end state solves that state once.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import type { RelightEngine } from '../../../src/engines/relight/RelightEngine';
import { SOLUTION_CACHE_SIZE } from '../../../src/engines/relight/solutionCache';
import type { LitMaps } from '../../../src/engines/relight/relightMaps';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { relightTestRoom, relightTestSettings, threeLampScenes, fadeScenes } from './threeLampScenes';

const gl = withHeadlessGL();
const SETTINGS = relightTestSettings(5);
const room = relightTestRoom;
/** Three spots with per-lamp dimming and colour (a light scene's look as toLightingScene hands it over). */
const scene = threeLampScenes({ flux: [1000, 300], beamDegrees: 30, pitchStep: 15, x: [0.8, 1.2], z: [0.9, 0.5] });
const { A, B } = fadeScenes(scene);
const C = scene([
  [0.5, [1, 1, 1]],
  [0, [1, 1, 1]],
  [1, [1, 1, 1]],
]);

/** A copy of every receiver's direct and total map. */
function snapshot(lit: LitMaps): { direct: Float32Array; total: Float32Array }[] {
  const r = SURFACE_NAMES.map((n) => lit.maps[n]);
  return r.map((m) => ({ direct: m.direct.slice(), total: m.total.slice() }));
}

function solved(engine: RelightEngine, s: BakeScene) {
  engine.setScene(s);
  engine.finish();
  return snapshot(engine.maps());
}

describe('crossfade between two light scenes', () => {
  it('the map at e = 0, 0.25, 0.5, 1 is (1 − e)·A + e·B; the fade adds relights but no group bake and no indirect solve', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      const a = solved(engine, A);
      const b = solved(engine, B);
      const before = { ...engine.counters };
      expect(before).toMatchObject({ groupBakes: 3, indirectSolves: 2 });
      const peak = Math.max(...[...a, ...b].flatMap((m) => [...m.total]));
      expect(peak).toBeGreaterThan(1);
      const ms: number[] = [];
      for (const e of [0, 0.25, 0.5, 1]) {
        engine.setFade({ from: A, e });
        // Nothing to bake or solve during the fade: both ends are solved.
        expect(engine.progress).toMatchObject({ done: true, exact: true });
        const t0 = performance.now();
        const lit = snapshot(engine.maps());
        ms.push(performance.now() - t0);
        let worst = 0;
        lit.forEach((m, r) => {
          for (let i = 0; i < m.total.length; i++) {
            worst = Math.max(worst, Math.abs(m.total[i] - ((1 - e) * a[r].total[i] + e * b[r].total[i])));
            worst = Math.max(worst, Math.abs(m.direct[i] - ((1 - e) * a[r].direct[i] + e * b[r].direct[i])));
          }
        });
        // Float32 sums of a few terms: 1e-5 of the peak.
        expect(worst, `e = ${e}`).toBeLessThan(1e-5 * peak);
        engine.step();
      }
      console.info(`crossfade relight of ${SURFACE_NAMES.length} surfaces, 3 groups: ${ms.map((x) => x.toFixed(2)).join(', ')} ms`);
      expect(engine.counters.groupBakes).toBe(before.groupBakes);
      expect(engine.counters.indirectSolves).toBe(before.indirectSolves);
      expect(engine.counters.relights).toBe(before.relights + 4);
      engine.setFade(null);
    } finally {
      engine.dispose();
    }
  });

  it('a scene recalled after others is exact at once from the kept solution: no re-solve', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      const a = solved(engine, A);
      solved(engine, B);
      const solves = engine.counters.indirectSolves;
      engine.setScene(A);
      expect(engine.progress).toMatchObject({ done: true, exact: true });
      const again = snapshot(engine.maps());
      again.forEach((m, r) => expect(Array.from(m.total)).toEqual(Array.from(a[r].total)));
      expect(engine.counters.indirectSolves).toBe(solves);
      expect(SOLUTION_CACHE_SIZE).toBeGreaterThanOrEqual(2);
    } finally {
      engine.dispose();
    }
  });

  it('a fade to a new end state solves that state once (and only it), with no group bake; its end equals the scene baked alone', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      solved(engine, B);
      const bakes = engine.counters.groupBakes;
      const solves = engine.counters.indirectSolves;
      engine.setScene(C);
      for (const e of [0.1, 0.4, 0.7]) {
        engine.setFade({ from: B, e });
        engine.maps();
        engine.step(4);
      }
      engine.finish();
      expect(engine.counters.indirectSolves).toBe(solves + 1);
      expect(engine.counters.groupBakes).toBe(bakes);
      engine.setFade({ from: B, e: 1 });
      const end = snapshot(engine.maps());
      const fresh = createRelightEngine(gl, SETTINGS);
      try {
        const c = solved(fresh, C);
        end.forEach((m, r) => m.total.forEach((v, i) => expect(Math.abs(v - c[r].total[i])).toBeLessThan(1e-4 * Math.max(1, c[r].total[i]))));
      } finally {
        fresh.dispose();
      }
    } finally {
      engine.dispose();
    }
  });

  it('refuses a fade from a scene with other luminaires and a fraction outside [0, 1]', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      engine.setScene(A);
      expect(() => engine.setFade({ from: { room, luminaires: A.luminaires.slice(0, 2) }, e: 0.5 })).toThrow('other luminaires');
      expect(() => engine.setFade({ from: B, e: 1.5 })).toThrow('outside [0, 1]');
    } finally {
      engine.dispose();
    }
  });
});
