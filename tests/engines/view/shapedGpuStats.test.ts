/**
 * A room of any shape's floor and work-plane statistics on the GPU (docs/viewer.md, "Statistics on
 * the GPU"): the floor reduced over its atlas texels, each weighed by its coverage
 * (shapedFloorWeights.ts), the work plane from its per-basis and per-solution grids over the outline
 * (workPlaneBases.ts createShapedWorkPlaneBases), both in the view's context at the relight's
 * weights, against the CPU's floorStats and workPlaneStats on the CPU relight of the same engine.
 * Headless-gl on both sides; no map is read back.
 */
import { describe, expect, it } from 'vitest';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { encloseShapedRoom } from '../../../src/engines/bake/shapedRoom/encloseShapedRoom';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { createViewRelight } from '../../../src/engines/view/createViewRelight';
import { floorStats, workPlaneStats, type IlluminanceStats } from '../../../src/engines/view/lightStats';
import { shapedFloorWeights } from '../../../src/engines/view/shapedFloorWeights';
import { createWorkPlaneBases } from '../../../src/engines/view/workPlaneBases';
import { isotropic } from '../../reference/photometryFixtures';
import { withHeadlessGL } from '../bake/withHeadlessGL';
import { shapedBakeRoom } from '../bake/shapedRoomKit';
import { headlessRenderer } from './headlessRenderer';

const bakeGl = withHeadlessGL();
const renderer = headlessRenderer(16, 16);
const SETTINGS = { texelSize: 0.2, maxTextureSize: 64, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 1, seed: 3 };
const HEIGHT = 0.8;
/** An L: 4 × 3.5 m with a 1.6 × 1.5 m notch, so the outline leaves points out and the inner corner casts shadows. */
const input: RoomInput = {
  outline: [
    [0, 0],
    [4, 0],
    [4, 2],
    [2.4, 2],
    [2.4, 3.5],
    [0, 3.5],
  ],
  height: 2.6,
  reflectance: { floor: 0.4, ceiling: 0.8, walls: 0.6 },
};
const lamp = (photometry: BakeScene['luminaires'][number]['photometry'], position: Vec3, dimming: number, color: Vec3): BakeScene['luminaires'][number] => ({ photometry, position, yaw: 0, pitch: 0, roll: 0, dimming, color });
// One photometry object per type for every scene: a group is known by its photometry (a new object would be a new group to bake).
const TYPES = [isotropic(1500), isotropic(900)];
const ROOM = shapedBakeRoom(input);
const scene = (d: [number, number]): BakeScene => ({
  room: ROOM,
  luminaires: [lamp(TYPES[0], [3.3, 2.2, 1], d[0], [1, 0.85, 0.7]), lamp(TYPES[1], [1, 2.4, 2.8], d[1], [0.9, 0.95, 1])],
});

function settled(p: { poll(): IlluminanceStats | null } | null): IlluminanceStats {
  if (!p) throw new Error('no statistics request');
  for (let i = 0; i < 10000; i++) {
    const s = p.poll();
    if (s) return s;
  }
  throw new Error('the statistics fence never signalled');
}

const relative = (a: number, b: number) => Math.abs(a / b - 1);

describe('a shaped room’s statistics on the GPU', () => {
  it('floor and work plane: Ē, Emin, Emax, U0 match the CPU within 1e-6 relative at the baked look and at an interim dimming; no map read back', () => {
    const engine = createRelightEngine(bakeGl, SETTINGS);
    const relight = createViewRelight(renderer, 'float', null);
    try {
      const A = scene([1, 0.6]);
      engine.setScene(A);
      engine.finish();
      const prepared = prepareObjects(encloseShapedRoom(A).objects!, { texelSize: engine.settings.texelSize, maxAtlasSize: engine.settings.maxTextureSize });
      const weights = shapedFloorWeights(prepared)!;
      expect(weights.some((w) => w > 0 && w < 1)).toBe(true);
      const plane = createWorkPlaneBases(A, HEIGHT, 0.1, prepared);
      let worst = 0;
      const check = (shown: BakeScene) => {
        const parts = engine.relightParts()!;
        const maps = relight.relight(parts);
        const cpuFloor = floorStats(engine.maps(), prepared);
        const gpuFloor = settled(relight.shapedFloorStats(maps, weights));
        const cpuPlane = workPlaneStats(shown, engine.maps(), HEIGHT, 0.1, {}, prepared);
        const gpuPlane = settled(relight.workPlaneStats(parts, plane));
        expect(cpuFloor.avg).toBeGreaterThan(10);
        expect(cpuPlane.avg).toBeGreaterThan(10);
        expect(gpuPlane.points).toBe(cpuPlane.points);
        for (const [gpu, cpu] of [
          [gpuFloor, cpuFloor],
          [gpuPlane, cpuPlane],
        ]) {
          for (const key of ['avg', 'min', 'max', 'u0'] as const) {
            worst = Math.max(worst, relative(gpu[key], cpu[key]));
            expect(relative(gpu[key], cpu[key])).toBeLessThan(1e-6);
          }
        }
      };
      check(A);
      // A dimming: the interim indirect scaling until the re-solve (one term, scaled).
      const dimmed = scene([0.3, 1]);
      engine.setScene(dimmed);
      expect(engine.relightParts()!.terms[0].scale.some((s) => Math.abs(s - 1) > 1e-3)).toBe(true);
      check(dimmed);
      expect(relight.counters.mapReadbacks.count).toBe(0);
      expect(relight.counters.statsReadbacks).toEqual({ count: 4, bytes: 64 });
      console.info(`shaped room on the GPU: floor ${weights.filter((w) => w > 0).length} atlas texels, work plane ${plane.grid.nx}×${plane.grid.nz} points; worst statistic ${worst.toExponential(2)} relative to the CPU`);
    } finally {
      relight.dispose();
      engine.dispose();
    }
  }, 600_000);
});
