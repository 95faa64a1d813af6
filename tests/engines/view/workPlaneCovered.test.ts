/**
 * Work-plane statistics leave out what furniture occupies, as the floor's do (issue #27,
 * EN 12464-1): the points where a standing object rises through the plane. Checked against hand
 * sums over the points that remain.
 */
import { describe, expect, it } from 'vitest';
import type { BakeObject, BakeScene } from '../../../src/engines/bake/bakeScene';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { workPlaneStats } from '../../../src/engines/view/lightStats';
import { isotropic, uniformRoom } from '../bake/bakeTestKit';
import { boxMesh } from '../bake/objects/objectFixtures';

const box = (id: string, w: number, h: number, d: number, position: [number, number, number]): BakeObject => ({ id, mesh: boxMesh(w, h, d), position, yaw: 0, scale: 1 });

describe('work plane at 0.75 m with furniture', () => {
  // 4 × 3 × 4 m, black; a 2 m shelf (x 0.5…1.5, z 3.0…3.5), a coffee table below the plane, a desk
  // whose top is the plane, a box hung at 1.5 m.
  const objects = [box('shelf', 1, 2, 0.5, [1, 0, 3.25]), box('coffee-table', 1, 0.45, 0.6, [3, 0, 1]), box('desk', 1.2, 0.75, 0.6, [3, 0, 3]), box('hung', 0.8, 0.3, 0.4, [1, 1.5, 1])];
  const scene: BakeScene = { room: uniformRoom(4, 3, 4, 0), luminaires: [{ photometry: isotropic(800), position: [2, 2.6, 2], yaw: 0, pitch: 0, roll: 0 }], objects };
  const lit = emptyLitMaps(surfaceLayouts(scene.room, 0.1, 64));
  const prepared = prepareObjects(objects, { texelSize: 0.1 });
  const plane = workPlaneStats(scene, lit, 0.75, 0.25, {}, prepared);

  it('leaves out exactly the 4 × 2 points inside the shelf; the low table, the desk top and the hung box cover none', () => {
    expect([plane.nx, plane.nz]).toEqual([16, 16]);
    const expected: number[] = [];
    for (let k = 0; k < 16; k++) {
      for (let i = 0; i < 16; i++) {
        const [x, z] = [(i + 0.5) * 0.25, (k + 0.5) * 0.25];
        if (x > 0.5 && x < 1.5 && z > 3 && z < 3.5) expected.push(k * 16 + i);
      }
    }
    expect(expected).toHaveLength(8);
    expect([...plane.covered.keys()].filter((k) => plane.covered[k] === 1)).toEqual(expected);
  });

  it('Ē, Emin, Emax, U0 are the hand sums over the other 248 points', () => {
    let sum = 0;
    let min = Infinity;
    let max = -Infinity;
    let n = 0;
    plane.values.forEach((v, k) => {
      if (plane.covered[k]) return;
      sum += v;
      min = Math.min(min, v);
      max = Math.max(max, v);
      n++;
    });
    expect(n).toBe(248);
    expect(plane.points).toBe(248);
    expect(plane.avg).toBeCloseTo(sum / 248, 9);
    expect(plane.min).toBe(min);
    expect(plane.max).toBe(max);
    expect(plane.u0).toBeCloseTo(min / (sum / 248), 12);
    // The points inside the shelf are dark (its own faces block every lamp): counted, they would pull Ē and U0 down.
    plane.covered.forEach((c, k) => c && expect(plane.values[k]).toBe(0));
  });

  it('without objects nothing is left out', () => {
    const bare = workPlaneStats({ ...scene, objects: [] }, lit, 0.75, 0.25);
    expect(bare.points).toBe(256);
    expect(bare.covered.every((c) => c === 0)).toBe(true);
  });
});
