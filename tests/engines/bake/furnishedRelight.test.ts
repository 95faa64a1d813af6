/**
 * Objects and relighting (docs/baker.md, "Objects: passes" → Outputs): the relight engine's basis
 * bakes carry the objects' atlas, dimming and colour relight it without a bake, moving an object
 * rebakes every group, and combineMaps sums the atlas like the walls. Direct light is linear
 * exactly, so relit direct maps equal a full bake of the dimmed, coloured scene to float rounding.
 */
import { describe, expect, it } from 'vitest';
import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { combineMaps } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { createRelightEngine } from '../../../src/engines/relight/createRelightEngine';
import { boxMesh } from './objects/objectFixtures';
import { isotropic, spot, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const SETTINGS = { texelSize: 0.15, maxTextureSize: 64, samples: 16, bounces: 1, samplesPerDraw: 8, blurRadius: 1, seed: 3 };
const table: BakeObject = { id: 'table', mesh: boxMesh(0.8, 0.7, 0.6, 0.6), position: [1.2, 0, 1.3], yaw: 20, scale: 1 };
const lamp = (x: number, dimming: number, color: Rgb) => ({ photometry: spot(800, 30, 10, 2), position: [x, 2.3, 1.4] as [number, number, number], yaw: 0, pitch: 0, roll: 0, dimming, color });
const scene: BakeScene = {
  room: uniformRoom(2.6, 2.5, 2.8, 0.5),
  luminaires: [lamp(0.9, 0.5, [1, 0.8, 0.6]), lamp(1.7, 1, [1, 1, 1]), { photometry: isotropic(30), position: [2.2, 1.2, 0.4], yaw: 0, pitch: 0, roll: 0, dimming: 0.3 }],
  objects: [table],
};

function maxAbsDiff(a: Float32Array, b: Float32Array): number {
  let m = 0;
  for (let i = 0; i < a.length; i++) m = Math.max(m, Math.abs(a[i] - b[i]));
  return m;
}

describe('objects in relighting', () => {
  it('relit atlas direct = a full bake of the dimmed, coloured scene; moving an object rebakes every group', () => {
    const engine = createRelightEngine(gl, SETTINGS);
    try {
      engine.setScene(scene);
      engine.finish();
      const relit = engine.maps().maps.objects!;
      const full = createBaker(gl).bake(scene, SETTINGS).maps.objects!;
      const peak = Math.max(...full.direct);
      expect(peak).toBeGreaterThan(0);
      expect(relit.direct.length).toBe(full.direct.length);
      expect(maxAbsDiff(relit.direct, full.direct)).toBeLessThan(1e-5 * peak);
      // Dimming alone: no bake.
      const bakes = engine.counters.groupBakes;
      const dimmed = { ...scene, luminaires: scene.luminaires.map((l, k) => (k === 0 ? { ...l, dimming: 0.1 } : l)) };
      expect(engine.setScene(dimmed).bake).toBe(0);
      engine.finish();
      expect(engine.counters.groupBakes).toBe(bakes);
      // A moved object is a new scene: all three groups bake again.
      expect(engine.setScene({ ...dimmed, objects: [{ ...table, position: [1.3, 0, 1.3] }] }).bake).toBe(3);
    } finally {
      engine.dispose();
    }
  });

  it('combineMaps sums the atlas maps with the weights', () => {
    const baker = createBaker(gl);
    const a = baker.bake({ ...scene, luminaires: [scene.luminaires[0]] }, SETTINGS).maps;
    const b = baker.bake({ ...scene, luminaires: [scene.luminaires[1]] }, SETTINGS).maps;
    const sum = combineMaps([
      { maps: a, weight: 2 },
      { maps: b, weight: [1, 0.5, 0.25] },
    ]);
    const o = sum.objects!;
    expect(o.atlas).toBe(a.objects!.atlas);
    for (const kind of ['direct', 'indirect', 'total'] as const) {
      for (let i = 0; i < o[kind].length; i++) {
        const expected = 2 * a.objects![kind][i] + [1, 0.5, 0.25][i % 3] * b.objects![kind][i];
        expect(Math.abs(o[kind][i] - expected)).toBeLessThanOrEqual(1e-6 * Math.max(1, Math.abs(expected)));
      }
    }
  });
});
