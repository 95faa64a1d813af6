/**
 * The work plane's statistics on the GPU (docs/viewer.md, "Work-plane statistics on the GPU"): the
 * per-basis direct grids and the per-solution floor-indirect grids (workPlaneBases.ts) combined in
 * the view's context with the relight's weights and reduced by the statistics pass, against the CPU
 * formula (lightStats.ts workPlaneStats) on the CPU relight of the same engine at the same weights.
 * Headless-gl on both sides: the engine bakes on one context, the view relights on three's.
 */
import { describe, expect, it } from 'vitest';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { groupLuminaires, groupWeight } from '../../../src/engines/relight/luminaireGroups';
import { createViewRelight } from '../../../src/engines/view/createViewRelight';
import { workPlaneStats, type IlluminanceStats } from '../../../src/engines/view/lightStats';
import { createWorkPlaneBases } from '../../../src/engines/view/workPlaneBases';
import { blendWeights } from '../../../src/engines/relight/groupState';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { relightTestSettings, threeLampScenes, fadeScenes } from '../relight/threeLampScenes';
import { headlessRenderer } from './headlessRenderer';

const bakeGl = withHeadlessGL();
const renderer = headlessRenderer(16, 16);
const SETTINGS = relightTestSettings(5);
/** Three spots with per-lamp dimming and colour (a light scene's look as toLightingScene hands it over). */
const scene = threeLampScenes({ flux: [1500, 400], beamDegrees: 40, pitchStep: 12, x: [0.7, 1.3], z: [0.8, 0.6] });
const { A, B } = fadeScenes(scene, 0.7);
const HEIGHT = 0.8;

/** The scene at fade fraction e from `from` to `to`, as the CPU formula's point sources see it: each luminaire at dimming 1 with its blended group weight as colour. */
function blended(from: BakeScene, to: BakeScene, e: number): BakeScene {
  const groups = groupLuminaires(to.luminaires);
  const luminaires = to.luminaires.map((l, i) => {
    const g = groups.find((gr) => gr.members.includes(i))!;
    return { ...l, dimming: 1, color: blendWeights(groupWeight(g, from.luminaires), groupWeight(g, to.luminaires), e) };
  });
  return { ...to, luminaires };
}

function settled(p: { poll(): IlluminanceStats | null } | null): IlluminanceStats {
  if (!p) throw new Error('no work-plane statistics request');
  for (let i = 0; i < 10000; i++) {
    const s = p.poll();
    if (s) return s;
  }
  throw new Error('the statistics fence never signalled');
}

const relative = (a: number, b: number) => Math.abs(a / b - 1);

describe('work-plane statistics on the GPU', () => {
  const engine = createRelightEngine(bakeGl, SETTINGS);
  engine.setScene(A);
  engine.finish();
  engine.setScene(B);
  engine.finish();

  it('the indirect solutions are non-negative: the work plane is linear in the weights and the term scales (the CPU formula clamps only float cancellation)', () => {
    engine.setFade({ from: A, e: 0.5 });
    const terms = engine.relightParts()!.terms;
    engine.setFade(null);
    expect(terms.length).toBe(2);
    for (const { solution } of terms) expect(Math.min(...solution.surfaces.floor)).toBeGreaterThanOrEqual(0);
  });

  it('a crossfade and an interim dimming: Ē, Emin, Emax, U0 from the GPU match the CPU work plane within 1e-5 relative, read as 16-byte texels, no map read back', () => {
    const relight = createViewRelight(renderer, 'half', null);
    const plane = createWorkPlaneBases(B, HEIGHT);
    try {
      let worst = 0;
      const check = (shown: BakeScene) => {
        const parts = engine.relightParts()!;
        relight.relight(parts);
        const gpu = settled(relight.workPlaneStats(parts, plane));
        const cpu = workPlaneStats(shown, engine.maps(), HEIGHT, 0.1, {}, null);
        expect(cpu.avg).toBeGreaterThan(10);
        expect(gpu.points).toBe(cpu.points);
        for (const key of ['avg', 'min', 'max', 'u0'] as const) {
          worst = Math.max(worst, relative(gpu[key], cpu[key]));
          expect(relative(gpu[key], cpu[key])).toBeLessThan(1e-5);
        }
      };
      for (const e of [0, 0.35, 0.8, 1]) {
        engine.setFade({ from: A, e });
        check(blended(A, B, e));
      }
      engine.setFade(null);
      // A dimming: the indirect light is the Φ-scaled interim until the re-solve (one term, scaled).
      const dimmed = scene([
        [0.2, [1, 0.8, 0.6]],
        [0.45, [0.9, 0.95, 1]],
        [0.7, [1, 0.7, 0.4]],
      ]);
      engine.setScene(dimmed);
      expect(engine.relightParts()!.terms[0].scale.some((s) => Math.abs(s - 1) > 1e-3)).toBe(true);
      check(dimmed);
      expect(relight.counters.mapReadbacks.count).toBe(0);
      expect(relight.counters.statsReadbacks).toEqual({ count: 5, bytes: 80 });
      console.info(`work plane on the GPU: ${plane.grid.nx}×${plane.grid.nz} points, worst statistic ${worst.toExponential(2)} relative to the CPU`);
      engine.setScene(B);
      engine.finish();
    } finally {
      relight.dispose();
    }
  });

  it('points inside furniture are left out as on the CPU: a covered block changes the count and the statistics to those of the points left', () => {
    const relight = createViewRelight(renderer, 'float', null);
    const plane = createWorkPlaneBases(B, HEIGHT);
    try {
      const parts = engine.relightParts()!;
      relight.relight(parts);
      const cpu = workPlaneStats(B, engine.maps(), HEIGHT);
      // Cover the brightest tenth of the points by hand (the mask the statistics take, as workPlaneUnderObjects writes it).
      const order = [...cpu.values.keys()].sort((a, b) => cpu.values[b] - cpu.values[a]);
      plane.grid.covered.fill(0);
      for (const k of order.slice(0, Math.floor(order.length / 10))) plane.grid.covered[k] = 1;
      const left = cpu.values.filter((_, k) => plane.grid.covered[k] === 0);
      const gpu = settled(relight.workPlaneStats(parts, plane));
      expect(gpu.points).toBe(left.length);
      const sum = left.reduce((s, v) => s + v, 0);
      expect(relative(gpu.avg, sum / left.length)).toBeLessThan(1e-5);
      expect(relative(gpu.max, Math.max(...left))).toBeLessThan(1e-5);
      expect(gpu.max).toBeLessThan(cpu.max);
      expect(relative(gpu.min, Math.min(...left))).toBeLessThan(1e-5);
    } finally {
      relight.dispose();
    }
  });
});
