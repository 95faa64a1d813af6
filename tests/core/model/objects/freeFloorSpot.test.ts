/** New furniture goes to free floor (issue #27, "Furniture"): the nearest lattice point where it overlaps nothing and fits the room. */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../../src/core/catalog/defaultCatalog';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { freeFloorSpot } from '../../../../src/core/model/objects/freeFloorSpot';
import { furnitureMesh } from '../../../../src/core/model/objects/furniture/furnitureLibrary';
import { objectMesh, placedBounds } from '../../../../src/core/model/objects/objectGeometry';
import { createConfiguratorStore } from '../../../../src/core/store/createConfiguratorStore';
import { createRng } from '../../../fuzz/mutate';

function withItems(items: { item: string; x: number; z: number }[], room = { width: 5, depth: 4, height: 2.8 }): Configuration {
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration(room) });
  for (const { item, x, z } of items) expect(store.getState().dispatch('addObject', { source: { kind: 'library', item }, placement: { on: 'floor', x, z } })).toEqual({ ok: true });
  return store.getState().config;
}

function footprints(config: Configuration) {
  return config.objects.map((o) => placedBounds(o, objectMesh(config, o.id), config.room));
}

describe('freeFloorSpot', () => {
  it('an empty room: the spot asked for', () => {
    expect(freeFloorSpot(withItems([]), furnitureMesh('coffee-table'), { x: 2.5, z: 2 })).toEqual({ x: 2.5, z: 2 });
  });

  it('a coffee table asked for where the sofa stands goes beside it, as near as the lattice allows, overlapping nothing', () => {
    const config = withItems([{ item: 'sofa', x: 2.5, z: 2 }]);
    const spot = freeFloorSpot(config, furnitureMesh('coffee-table'), { x: 2.5, z: 2 })!;
    // Sofa 210 × 90 cm (z 1.55…2.45), table 120 × 60 cm: the nearest free centre is 0.45 + 0.30 + 0.02 m off in z, on the 5 cm lattice.
    expect(spot.x).toBe(2.5);
    expect(Math.abs(spot.z - 2)).toBeCloseTo(0.8, 9);
    const sofa = footprints(config)[0];
    const table = { x0: spot.x - 0.6, x1: spot.x + 0.6, z0: spot.z - 0.3, z1: spot.z + 0.3 };
    expect(table.z1 <= sofa.min[2] || table.z0 >= sofa.max[2]).toBe(true);
  });

  it('random rooms and pieces: every spot returned fits the room and overlaps no piece (seeded)', () => {
    const rng = createRng(27);
    const items = ['sofa', 'armchair', 'dining-table', 'coffee-table', 'sideboard', 'floor-plant', 'desk', 'bed'];
    for (let run = 0; run < 40; run++) {
      const placed: { item: string; x: number; z: number }[] = [];
      let config = withItems([], { width: 6, depth: 5, height: 2.8 });
      for (let n = 0; n < 5; n++) {
        const item = items[Math.floor(rng.next() * items.length)];
        const spot = freeFloorSpot(config, furnitureMesh(item), { x: rng.next() * 6, z: rng.next() * 5 });
        if (!spot) continue;
        placed.push({ item, ...spot });
        config = withItems(placed, { width: 6, depth: 5, height: 2.8 });
        const boxes = footprints(config);
        const last = boxes[boxes.length - 1];
        expect(last.min[0]).toBeGreaterThanOrEqual(-1e-9);
        expect(last.max[0]).toBeLessThanOrEqual(6 + 1e-9);
        expect(last.min[2]).toBeGreaterThanOrEqual(-1e-9);
        expect(last.max[2]).toBeLessThanOrEqual(5 + 1e-9);
        for (const other of boxes.slice(0, -1)) {
          const apart = last.max[0] <= other.min[0] || last.min[0] >= other.max[0] || last.max[2] <= other.min[2] || last.min[2] >= other.max[2];
          expect(apart).toBe(true);
        }
      }
    }
  });

  it('a room with no room left: null', () => {
    const config = withItems([{ item: 'bed', x: 1, z: 1.1 }], { width: 2, depth: 2.2, height: 2.8 });
    expect(freeFloorSpot(config, furnitureMesh('sofa'), { x: 1, z: 1 })).toBeNull();
  });
});
