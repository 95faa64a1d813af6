/** resolveBakeScene with objects (docs/scene-format.md, "Objects"): meshes loaded once, ids, the room check. */
import { describe, expect, it } from 'vitest';
import type { LightingScene } from '../../../src/core/model/lightingScene/lightingScene';
import type { TriangleMesh } from '../../../src/core/mesh/triangleMesh';
import type { Photometry } from '../../../src/core/photometry/types';
import { InputError } from '../../../src/core/inputError';
import { resolveBakeScene, resolveBakeSceneSync, SceneObjectError } from '../../../src/engines/bake/resolveBakeScene';

/** A 1 m cube with its origin at the centre of its bottom face (only its bounds matter here). */
const cube: TriangleMesh = {
  positions: new Float32Array([-0.5, 0, -0.5, 0.5, 0, -0.5, 0.5, 1, 0.5, -0.5, 1, 0.5]),
  indices: new Uint32Array([0, 1, 2, 0, 2, 3]),
  materialOfTriangle: new Uint16Array([0, 0]),
  materials: [{ name: 'm', reflectance: [0.5, 0.5, 0.5] }],
};

const scene = (objects: LightingScene['objects']): LightingScene => ({
  version: 2,
  room: { width: 4, height: 2.5, depth: 3, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
  luminaires: [],
  objects,
});
const noPhotometry = (): Photometry => {
  throw new Error('no luminaires here');
};

describe('resolveBakeScene: objects', () => {
  it('loads each distinct mesh once, gives ids (given, else objects[i]) and keeps placement and reflectance', async () => {
    const asked: string[] = [];
    const s = scene([
      { mesh: 'a.obj', position: [1, 0, 1], yaw: 90, scale: 1, id: 'table' },
      { mesh: 'a.obj', position: [3, 0, 2], yaw: 0, scale: 0.5, reflectance: 0.3 },
    ]);
    const out = await resolveBakeScene(s, noPhotometry, async (p) => {
      asked.push(p);
      return cube;
    });
    expect(asked).toEqual(['a.obj']);
    expect(out.objects).toEqual([
      { id: 'table', mesh: cube, position: [1, 0, 1], yaw: 90, scale: 1 },
      { id: 'objects[1]', mesh: cube, position: [3, 0, 2], yaw: 0, scale: 0.5, reflectance: 0.3 },
    ]);
    expect(resolveBakeSceneSync(s, noPhotometry, () => cube).objects).toEqual(out.objects);
  });

  it('no objects: no objects field (the baker compiles the empty room)', async () => {
    expect('objects' in (await resolveBakeScene(scene([]), noPhotometry))).toBe(false);
  });

  it.each([
    // The cube spans x ± 0.5 around its origin: at x = 3.52 it reaches 4.02 m, 2 cm past the 4 m east wall.
    [[3.52, 0, 1.5], 'objects[0]: the placed mesh reaches 0.0200 m beyond the east wall (x = 4 m) (the room is 4 m wide); objects must be inside the room (1 cm tolerance)'],
    [[2, -0.3, 1.5], 'objects[0]: the placed mesh reaches 0.300 m beyond the floor (y = 0) (the room is 2.5 m high); objects must be inside the room (1 cm tolerance)'],
    [[2, 0, 0.2], 'objects[0]: the placed mesh reaches 0.300 m beyond the north wall (z = 0) (the room is 3 m deep); objects must be inside the room (1 cm tolerance)'],
  ] as const)('an object at %j leaves the room', async (position, message) => {
    const s = scene([{ mesh: 'a.obj', position: [...position], yaw: 0, scale: 1 }]);
    await expect(resolveBakeScene(s, noPhotometry, () => cube)).rejects.toThrow(new SceneObjectError(0, message.slice('objects[0]'.length)));
    expect(() => resolveBakeSceneSync(s, noPhotometry, () => cube)).toThrow(message);
  });

  it('within the 1 cm tolerance (a model dipping 5 mm into the floor) is accepted; yaw and scale count', async () => {
    await expect(resolveBakeScene(scene([{ mesh: 'a.obj', position: [2, -0.005, 1.5], yaw: 0, scale: 1 }]), noPhotometry, () => cube)).resolves.toBeTruthy();
    // Turned 45°, the cube's corners reach 0.707 m from its origin: at x = 3.4 that is 4.107 m.
    await expect(resolveBakeScene(scene([{ mesh: 'a.obj', position: [3.4, 0, 1.5], yaw: 45, scale: 1 }]), noPhotometry, () => cube)).rejects.toThrow(/reaches 0\.107 m beyond the east wall/);
    // Scaled ×3 it is 3 m tall: 0.5 m through the 2.5 m ceiling.
    await expect(resolveBakeScene(scene([{ mesh: 'a.obj', position: [2, 0, 1.5], yaw: 0, scale: 3 }]), noPhotometry, () => cube)).rejects.toThrow(/reaches 0\.500 m beyond the ceiling/);
  });

  it("a loader's failure names the object and keeps the loader's message", async () => {
    const s = scene([
      { mesh: 'ok.obj', position: [1, 0, 1], yaw: 0, scale: 1 },
      { mesh: 'models/bad.obj', position: [2, 0, 1], yaw: 0, scale: 1 },
    ]);
    const load = (p: string) => {
      if (p === 'ok.obj') return cube;
      throw new InputError('bad.obj: line 3: face refers to vertex 9, but 3 vertices are defined so far');
    };
    const error = await resolveBakeScene(s, noPhotometry, load).catch((e: unknown) => e);
    expect(error).toBeInstanceOf(SceneObjectError);
    expect((error as SceneObjectError).object).toBe(1);
    expect((error as Error).message).toBe('objects[1].mesh: bad.obj: line 3: face refers to vertex 9, but 3 vertices are defined so far');
    expect(() => resolveBakeSceneSync(s, noPhotometry, load)).toThrow('objects[1].mesh: bad.obj: line 3');
  });
});
