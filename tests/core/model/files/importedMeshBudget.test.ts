/**
 * addObject keeps every imported mesh of a configuration within the share of the 1 MB file the
 * meshes may take (MAX_STORED_MESH_CHARS), so a configuration built by actions always saves and
 * reopens (issue 32). The importer checks each model alone; this checks them together.
 */
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { createConfiguration } from '../../../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { MAX_STORED_MESH_CHARS, storedMeshChars } from '../../../../src/core/model/files/storedMeshSize';
import type { TriangleMesh } from '../../../../src/core/mesh/triangleMesh';
import { catalog, run } from '../helpers';

/** An n×n grid of 1 m on the floor: 2n² triangles on (n+1)² shared vertices. */
function grid(n: number): TriangleMesh {
  const positions: number[] = [];
  const indices: number[] = [];
  for (let j = 0; j <= n; j++) for (let i = 0; i <= n; i++) positions.push(i / n, 0, j / n);
  for (let j = 0; j < n; j++)
    for (let i = 0; i < n; i++) {
      const a = j * (n + 1) + i;
      indices.push(a, a + n + 1, a + n + 2, a, a + n + 2, a + 1);
    }
  return { positions: new Float32Array(positions), indices: new Uint32Array(indices), materialOfTriangle: new Uint16Array(indices.length / 3), materials: [{ name: 'floor', reflectance: [0.5, 0.5, 0.5] }] };
}

describe('imported meshes together fit in a file that reopens', () => {
  it('a second 0.54 MB mesh is refused with both numbers; the first saves and reopens', () => {
    const mesh = grid(100);
    expect(storedMeshChars('a.obj', mesh)).toBeGreaterThan(MAX_STORED_MESH_CHARS / 2);
    const room = createConfiguration({ width: 10, depth: 10, height: 3 });
    const one = run(room, 'addObject', { source: { kind: 'import', name: 'a.obj', mesh, units: 'm' }, placement: { on: 'floor', x: 2, z: 2 } });
    const second = bindAction('addObject', { source: { kind: 'import', name: 'b.obj', mesh, units: 'm' }, placement: { on: 'floor', x: 6, z: 6 } }, catalog).isEnabled(one);
    expect(second).not.toBe(true);
    expect(second !== true && second.reason).toMatch(/^imported model 'b\.obj': the imported models would take 1\.\d\d MB of a saved configuration; at most 0\.90 MB fit$/);
    // Another object from the stored mesh costs nothing more.
    const two = run(one, 'addObject', { source: { kind: 'imported', mesh: Object.keys(one.importedMeshes)[0] }, placement: { on: 'floor', x: 6, z: 6 } });
    const text = serializeConfiguration(two, catalog);
    expect(text.length).toBeLessThan(1_000_000);
    expect(deserializeConfiguration(text, catalog).objects).toHaveLength(2);
  });
});
