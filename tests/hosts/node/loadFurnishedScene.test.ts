/** Node's scene loader with objects: meshes relative to the scene file, units, errors as one line naming the scene. */
import { describe, expect, it } from 'vitest';
import { mkdtempSync, writeFileSync, copyFileSync } from 'node:fs';
import { join } from 'node:path';
import { tmpdir } from 'node:os';
import { loadLightingSceneFile, loadLightingSceneFileAsync } from '../../../src/hosts/node/loadLightingSceneFile';
import { LightingSceneError } from '../../../src/core/model/lightingScene/parseLightingScene';

const FIXTURE = join(__dirname, '../../fixtures/models/furnished-room.json');

describe('loadLightingSceneFileAsync: a furnished scene', () => {
  it('loads the OBJ and the GLB table relative to the scene file, with ids and placements', async () => {
    const loaded = await loadLightingSceneFileAsync(FIXTURE);
    const objects = loaded.bakeScene.objects!;
    expect(objects.map((o) => o.id)).toEqual(['dining-table', 'objects[1]']);
    expect(objects.map((o) => o.mesh.indices.length / 3)).toEqual([60, 60]);
    expect(objects[0]).toMatchObject({ position: [1.3, 0, 1.5], yaw: 0, scale: 1 });
    expect(objects[1].reflectance).toBe(0.4);
    expect(objects[0].mesh.materials.map((m) => m.name)).toEqual(['top', 'legs']);
    expect([...loaded.meshes.keys()]).toEqual(['table.obj', 'table.glb']);
    expect(loaded.meshes.get('table.obj')!.units).toBe('m');
  });

  it('the synchronous loader reads OBJ objects and says glTF needs the asynchronous one', () => {
    expect(() => loadLightingSceneFile(FIXTURE)).toThrow(new LightingSceneError('furnished-room.json: objects[1].mesh: table.glb: glTF models need the asynchronous scene loader (loadLightingSceneFileAsync); this caller reads OBJ only'));
  });

  it('a missing mesh file and a table through the wall are one line naming the scene and the object', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'luxbox-furnished-'));
    copyFileSync(join(__dirname, '../../fixtures/models/table.obj'), join(dir, 'table.obj'));
    const write = (objects: unknown[]) => {
      const path = join(dir, 'scene.json');
      writeFileSync(
        path,
        JSON.stringify({
          version: 2,
          room: { width: 3, height: 2.5, depth: 2, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
          luminaires: [],
          objects,
        }),
      );
      return path;
    };
    await expect(loadLightingSceneFileAsync(write([{ mesh: 'models/gone.obj', position: [1, 0, 1] }]))).rejects.toThrow(new LightingSceneError('scene.json: objects[0].mesh: cannot read models/gone.obj (no such file)'));
    // The 1.2 m table centred 0.3 m from the west wall reaches 0.3 m through it (0.6 − 0.3).
    await expect(loadLightingSceneFileAsync(write([{ mesh: 'table.obj', position: [0.3, 0, 1] }]))).rejects.toThrow(
      new LightingSceneError('scene.json: objects[0]: the placed mesh reaches 0.300 m beyond the west wall (x = 0) (the room is 3 m wide); objects must be inside the room (1 cm tolerance)'),
    );
    // Without its MTL the table still loads, grey, with a warning kept for the report.
    const loaded = await loadLightingSceneFileAsync(write([{ mesh: 'table.obj', position: [1.5, 0, 1] }]));
    expect(loaded.meshes.get('table.obj')!.warnings).toEqual(['table.obj: material library table.mtl not found; its materials are grey 0.5']);
  });
});
