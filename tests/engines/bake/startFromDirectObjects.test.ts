/**
 * What the relight engine's shared solve needs from the baker (docs/baker.md, "Indirect-only
 * solves"): a direct-only bake (bounces 0) that reads back only the direct maps and records the
 * flux statistics only when its report asks, and startFromDirect with objects: fed a bake's own
 * direct maps (walls and the atlas as the bounces read it), it reproduces that bake's indirect
 * and total maps, the objects' atlas included.
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { boxMesh } from './objects/objectFixtures';
import { spot, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);
const SETTINGS = { texelSize: 0.2, maxTextureSize: 64, samples: 8, bounces: 1, samplesPerDraw: 8, blurRadius: 1, seed: 5 };
const table: BakeObject = { id: 'table', mesh: boxMesh(0.8, 0.7, 0.6, 0.6), position: [1.2, 0, 1.3], yaw: 20, scale: 1 };
const scene: BakeScene = {
  room: uniformRoom(2.6, 2.5, 2.8, [0.5, 0.45, 0.4]),
  luminaires: [{ photometry: spot(900, 30, 10, 2), position: [1.3, 2.3, 1.4], yaw: 0, pitch: 0, roll: 0, color: [1, 0.9, 0.7] }],
  objects: [table],
};

describe('direct-only bakes and indirect-only solves with objects', () => {
  it('a direct-only bake reads back only the direct maps; its report still has the direct flux of a full bake', () => {
    const full = baker.start(scene, SETTINGS);
    const fullDirect = full.readDirect();
    const fluxFull = full.report().bounceFlux[0];
    full.dispose();
    const job = baker.start(scene, { ...SETTINGS, bounces: 0 });
    try {
      const direct = job.readDirect();
      // Six surfaces and the atlas twice (as emitted and as shown), nothing else read back.
      expect(job.report().readbacks.count).toBe(8 + 2); // + the report's own: the stats row (recorded only now) and the atlas total (per-object lux)
      for (const n of SURFACE_NAMES) expect(direct.surfaces[n]).toEqual(fullDirect.surfaces[n]);
      expect(direct.objects!.emitted).toEqual(fullDirect.objects!.emitted);
      const report = job.report();
      expect(report.indirectEnabled).toBe(false);
      expect(fluxFull).toBeGreaterThan(10);
      expect(Math.abs(report.bounceFlux[0] - fluxFull)).toBeLessThan(1e-6 * fluxFull);
    } finally {
      job.dispose();
    }
  });

  it("startFromDirect with the objects and a bake's own direct maps reproduces its indirect and total maps", () => {
    const full = baker.start(scene, SETTINGS);
    full.run();
    const reference = full.readMaps();
    const direct = full.readDirect();
    full.dispose();
    const solve = baker.startFromDirect(scene.room, direct.surfaces, SETTINGS, { objects: scene.objects!, direct: direct.objects!.emitted });
    try {
      solve.run();
      const maps = solve.readMaps();
      let peak = 0;
      let worst = 0;
      const pairs = [...SURFACE_NAMES.map((n) => [maps[n], reference[n]] as const), [maps.objects!, reference.objects!] as const];
      for (const [a, b] of pairs) {
        for (const kind of ['direct', 'indirect', 'total'] as const) {
          for (let i = 0; i < b[kind].length; i++) {
            peak = Math.max(peak, b[kind][i]);
            worst = Math.max(worst, Math.abs(a[kind][i] - b[kind][i]));
          }
        }
      }
      expect(reference.objects!.indirect.some((v) => v > 0)).toBe(true);
      // The same inputs and seed through the same passes: equal but for float rounding.
      expect(worst).toBeLessThanOrEqual(1e-6 * peak);
    } finally {
      solve.dispose();
    }
  });

  it('startFromDirect with objects needs their atlas direct map, of the atlas size', () => {
    const zero = Object.fromEntries(SURFACE_NAMES.map((n) => [n, new Float32Array(1)])) as Record<(typeof SURFACE_NAMES)[number], Float32Array>;
    expect(() => baker.startFromDirect(scene.room, zero, SETTINGS, { objects: scene.objects!, direct: new Float32Array(3) })).toThrow(/objects' direct map has 1 texels, their atlas \d+×\d+/);
  });
});
