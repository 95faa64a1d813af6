/**
 * The relight engine's shared indirect solve (docs/viewer.md, "Relighting without rebaking"):
 * one solve per scene whatever the number of groups, one re-solve per change of weights, and
 * between a change and its re-solve the last solve scaled per channel by Φ_now/Φ_solve.
 */
import { describe, expect, it } from 'vitest';
import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import { reflectanceRgb, type BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { texelArea } from '../../../src/engines/bake/surfaceLayout';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { isotropic, spot } from '../bake/bakeTestKit';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { compareWithBake, reflectedDirectFlux, shownIndirect } from './relightTestKit';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.2, maxTextureSize: 32, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 1, seed: 11 };
const room: BakeScene['room'] = { width: 4, height: 2.6, depth: 3, reflectance: { floor: 0.3, ceiling: 0.8, north: [0.7, 0.5, 0.3], south: 0.6, west: 0.5, east: 0.4 } };
// One Photometry object per lamp: a group is keyed by the photometry's identity (luminaireGroups.ts).
const photometries = Array.from({ length: 11 }, (_, k) => spot(900 + 50 * k, 25, 10, 2));
const bulb = isotropic(80);
const lamp = (k: number, dimming = 1, color: Rgb = [1, 1, 1]) => ({
  photometry: photometries[k],
  position: [0.4 + 0.32 * k, 2.4, 0.6 + 0.17 * k] as [number, number, number],
  yaw: 0,
  pitch: 10 * (k % 3),
  roll: 0,
  dimming,
  color,
});
const lamps = (n: number) => Array.from({ length: n }, (_, k) => lamp(k));

describe('one shared indirect solve', () => {
  for (const n of [1, 3, 11]) {
    it(`a full bake of ${n} group(s) runs one indirect solve and ${n} direct bases`, () => {
      const engine = createRelightEngine(gl, SETTINGS);
      try {
        expect(engine.setScene({ room, luminaires: lamps(n) })).toEqual({ bake: n, reused: 0 });
        // Stepped as the viewer does (small slices, previews on), not just finish().
        let p = engine.progress;
        for (let i = 0; i < 10_000 && !p.done; i++) p = engine.step(4);
        expect(p).toMatchObject({ done: true, lit: true, exact: true, groupsDone: n, groups: n, fraction: 1 });
        expect(engine.counters.groupBakes).toBe(n);
        expect(engine.counters.indirectSolves).toBe(1);
      } finally {
        engine.dispose();
      }
    });
  }

  it('a weights-only change bakes no group and runs one re-solve; the previous solution stays on screen until it is done', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      const scene = { room, luminaires: lamps(3) };
      engine.setScene(scene);
      engine.finish();
      const dimmed = { room, luminaires: scene.luminaires.map((l, k) => (k === 1 ? { ...l, dimming: 0.4, color: [1, 0.7, 0.5] as Rgb } : l)) };
      expect(engine.setScene(dimmed)).toEqual({ bake: 0, reused: 3 });
      const shown = shownIndirect(engine.maps());
      const version = engine.version;
      let p = engine.progress;
      let steps = 0;
      for (; steps < 10_000 && !p.done; steps++) {
        p = engine.step(4);
        // No preview of a re-solve: the maps change once, when it is done.
        if (!p.done) expect(engine.version).toBe(version);
      }
      expect(steps).toBeGreaterThan(2);
      expect(engine.version).toBeGreaterThan(version);
      expect(engine.counters).toMatchObject({ groupBakes: 3, indirectSolves: 2, relightsOnly: 1 });
      // The re-solve replaced the scaled solution with the exact one.
      const exact = shownIndirect(engine.maps());
      expect(exact.some((m, r) => m.some((v, i) => Math.abs(v - shown[r][i]) > 1e-3))).toBe(true);
    } finally {
      engine.dispose();
    }
  });

  it('between a change and its re-solve the indirect shown is the last solve × Φ_now/Φ_solve; after it, the exact one', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    const rho = reflectanceRgb(room);
    try {
      const scene = { room, luminaires: lamps(3) };
      engine.setScene(scene);
      engine.finish();
      const solvedLit = engine.maps();
      const solved = shownIndirect(solvedLit);
      const fluxSolve = reflectedDirectFlux(solvedLit, rho);
      const changed: BakeScene = { room, luminaires: [lamp(0, 0.1), lamp(1, 1, [1, 0.5, 0.2]), lamp(2)] };
      engine.setScene(changed);
      const nowLit = engine.maps();
      const fluxNow = reflectedDirectFlux(nowLit, rho);
      const scale = fluxNow.map((f, c) => f / fluxSolve[c]);
      expect(scale[0]).toBeGreaterThan(0.5);
      expect(scale[0]).toBeLessThan(1);
      expect(scale[2]).toBeLessThan(scale[0]);
      const shown = shownIndirect(nowLit);
      let peak = 0;
      let worst = 0;
      shown.forEach((m, r) =>
        m.forEach((v, i) => {
          peak = Math.max(peak, solved[r][i]);
          worst = Math.max(worst, Math.abs(v - scale[i % 3] * solved[r][i]));
        }),
      );
      expect(peak).toBeGreaterThan(10);
      // Float rounding of total − direct (the engine stores total = direct + s·indirect in float32).
      expect(worst).toBeLessThan(1e-5 * peak);
      // Hence the shown indirect flux per channel is the solved flux × Φ_now/Φ_solve.
      const areaFlux = (maps: Float32Array[]) => {
        const f = [0, 0, 0];
        SURFACE_NAMES.forEach((n, r) => maps[r].forEach((v, i) => (f[i % 3] += v * texelArea(nowLit.layouts[n]))));
        return f;
      };
      const shownFlux = areaFlux(shown);
      const solvedFlux = areaFlux(solved);
      for (let c = 0; c < 3; c++) expect(Math.abs(shownFlux[c] - scale[c] * solvedFlux[c])).toBeLessThan(1e-5 * solvedFlux[c]);

      engine.finish();
      const reference = createBaker(gl).bake(changed, SETTINGS).maps;
      const d = compareWithBake(engine.maps(), reference);
      expect(d.total).toBeLessThan(1e-5 * d.peak);
    } finally {
      engine.dispose();
    }
  });

  it('all off: no solve, zero light, no NaN; a channel that was dark in the last solve shows 0 until the re-solve', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      engine.setScene({ room, luminaires: [lamp(0, 0), lamp(1, 0)] });
      engine.finish(); // the direct bases only: no light, nothing to solve
      expect(engine.progress).toMatchObject({ done: true, exact: true });
      expect(engine.counters.indirectSolves).toBe(0);
      const dark = engine.maps();
      for (const n of SURFACE_NAMES) expect(dark.maps[n].total.every((v) => v === 0)).toBe(true);

      // Switched on with red light only: solved once; then white: G and B had Φ_solve = 0.
      engine.setScene({ room, luminaires: [lamp(0, 1, [1, 0, 0]), lamp(1, 0)] });
      const before = shownIndirect(engine.maps());
      expect(before.every((m) => m.every((v) => v === 0))).toBe(true); // no solution yet: direct only
      engine.finish();
      expect(engine.counters.indirectSolves).toBe(1);
      engine.setScene({ room, luminaires: [lamp(0, 1, [1, 1, 1]), isotropicLamp()] });
      const lit = engine.maps();
      const ind = shownIndirect(lit);
      for (const m of ind) {
        expect(m.every(Number.isFinite)).toBe(true);
        for (let i = 0; i < m.length; i += 3) expect([m[i + 1], m[i + 2]]).toEqual([0, 0]);
      }
      expect(ind.some((m) => m.some((v, i) => i % 3 === 0 && v > 0))).toBe(true);
      engine.finish();
      const after = shownIndirect(engine.maps());
      expect(after.some((m) => m.some((v, i) => i % 3 === 2 && v > 0))).toBe(true);
      // Off again: the indirect shown is 0 at once (Φ_now = 0), finite.
      engine.setScene({ room, luminaires: [lamp(0, 0), { ...isotropicLamp(), dimming: 0 }] });
      expect(engine.progress.done).toBe(true);
      for (const m of shownIndirect(engine.maps())) expect(m.every((v) => v === 0)).toBe(true);
    } finally {
      engine.dispose();
    }
  });
});

function isotropicLamp() {
  return { photometry: bulb, position: [3.2, 1.3, 2.2] as [number, number, number], yaw: 0, pitch: 0, roll: 0 };
}
