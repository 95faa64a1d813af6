import { describe, expect, it } from 'vitest';
import { FURNISHED_PRESETS, diningRoom } from '../../../src/core/catalog/furnishedPresets';
import { billOfMaterials } from '../../../src/core/model/power/billOfMaterials';
import { findFurnitureItem } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { objectMesh, objectPlacement, placedBounds, sourceMesh } from '../../../src/core/model/objects/objectGeometry';
import { deserializeConfiguration, serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import { validate } from '../../../src/core/model/validation/validate';
import { catalog } from '../model/helpers';

describe('furnished presets', () => {
  for (const preset of FURNISHED_PRESETS) {
    it(`${preset.id}: valid, furnished, lit, and sane for the baker`, () => {
      const c = preset.build(catalog);
      expect(validate(c, catalog)).toEqual([]);
      expect(c.systems.length).toBeGreaterThan(0);
      expect(c.objects.length).toBeGreaterThanOrEqual(6);
      const scene = toLightingScene(c, catalog);
      expect(scene.version).toBe(2);
      expect(scene.objects!.length).toBe(c.objects.length);
      // every luminaire hangs at or above the head-room line and above every object
      const top = Math.max(...c.objects.map((o) => placedBounds(o, sourceMesh(c, o.source)!, c.room).max[1]));
      for (const l of scene.luminaires) {
        expect(l.position[1]).toBeGreaterThanOrEqual(catalog.suspension.minHeightAboveFloor - 1e-9);
        expect(l.position[1]).toBeGreaterThan(top);
      }
      // installed flux per floor area: 100–3000 lm/m² (EN 12464-1 asks 100–500 lx on the task for homes and shops; utilisation about 0.3–0.6)
      const perArea = billOfMaterials(c, catalog).lumens / (c.room.width * c.room.depth);
      expect(perArea).toBeGreaterThan(100);
      expect(perArea).toBeLessThan(3000);
      // object meshes carry reflectances the baker accepts, and the file round-trips
      for (const o of c.objects) expect(objectMesh(c, o.id).materials.every((m) => m.reflectance.every((v) => v >= 0 && v < 0.95))).toBe(true);
      expect(deserializeConfiguration(serializeConfiguration(c, catalog), catalog)).toEqual(c);
    });
  }

  it('the dining room hangs its pendant rail over the table, at the head-room line', () => {
    const c = diningRoom(catalog);
    const table = c.objects.find((o) => o.source.kind === 'library' && o.source.item === 'dining-table')!;
    const tb = placedBounds(table, sourceMesh(c, table.source)!, c.room);
    const scene = toLightingScene(c, catalog);
    for (const l of scene.luminaires) {
      expect(l.position[0]).toBeGreaterThan(tb.min[0]);
      expect(l.position[0]).toBeLessThan(tb.max[0]);
      expect(l.position[2]).toBeCloseTo(objectPlacement(table, c.room).position[2], 9);
      // 2.8 m ceiling − 0.8 m suspension = 2.0 m: 1.25 m above the 0.75 m top
      expect(l.position[1]).toBeCloseTo(2, 9);
    }
    expect(c.objects.filter((o) => o.source.kind === 'library' && findFurnitureItem(o.source.item)?.id === 'chair').length).toBe(6);
  });
});
