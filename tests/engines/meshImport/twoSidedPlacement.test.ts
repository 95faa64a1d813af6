/**
 * Two-sided surfaces and placement (issue #35): the back side lies on the file's corners, so a rug
 * lying on the floor (an open OBJ quad at y = 0) is placed as the file has it, nothing below the floor.
 */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { positionBounds } from '../../../src/core/mesh/triangleMesh';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { importMesh } from '../../../src/engines/meshImport/importMesh';
import { insideOut, objText, quadMesh } from '../../core/mesh/orientFixtures';
import { textFile } from './modelFixtures';

describe('two-sided imports in the room', () => {
  it('a rug (an open quad on y = 0, wound either way) imports with its lowest point on the floor and is added to the floor', async () => {
    for (const quad of [quadMesh(), insideOut(quadMesh())]) {
      const r = await importMesh([textFile('rug.obj', objText(quad))]);
      expect(r.orientation).toMatchObject({ twoSided: 1, backTriangles: 2 });
      expect(positionBounds(r.mesh.positions).min[1]).toBe(0);
      const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
      const result = store.getState().dispatch('addObject', { source: { kind: 'import', name: r.name, mesh: r.mesh, units: r.units }, placement: { on: 'floor', x: 2, z: 2 } });
      expect(result).toEqual({ ok: true });
      expect(store.getState().config.objects).toHaveLength(1);
    }
  });
});
