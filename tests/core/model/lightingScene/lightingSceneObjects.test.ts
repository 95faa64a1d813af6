/** Lighting scene version 2 `objects` (docs/scene-format.md, "Objects"): fields, defaults, strictness. */
import { describe, expect, it } from 'vitest';
import { LightingSceneError, parseLightingScene, SCENE_LIMITS } from '../../../../src/core/model/lightingScene/parseLightingScene';

const scene = (objects: unknown, extra: Record<string, unknown> = {}) => ({
  version: 2,
  room: { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
  luminaires: [],
  objects,
  ...extra,
});
const refusal = (json: unknown): string => {
  try {
    parseLightingScene(json, 'scene.json');
  } catch (error) {
    expect(error).toBeInstanceOf(LightingSceneError);
    return (error as Error).message;
  }
  throw new Error('accepted');
};

describe('lighting scene objects', () => {
  it('reads an object with every field, and fills yaw 0 and scale 1 when absent', () => {
    const s = parseLightingScene(
      scene([
        { mesh: 'models/table.obj', position: [2.5, 0, 2], yaw: 30, scale: 1.5, reflectance: [0.5, 0.4, 0.3], id: 'table' },
        { mesh: 'models/chair.glb', position: [1, 0, 1] },
        { mesh: 'object:o12', position: [3, 0, 3], reflectance: 0.2 },
      ]),
      's',
    );
    expect(s.objects).toEqual([
      { mesh: 'models/table.obj', position: [2.5, 0, 2], yaw: 30, scale: 1.5, reflectance: [0.5, 0.4, 0.3], id: 'table' },
      { mesh: 'models/chair.glb', position: [1, 0, 1], yaw: 0, scale: 1 },
      { mesh: 'object:o12', position: [3, 0, 3], yaw: 0, scale: 1, reflectance: 0.2 },
    ]);
  });

  it('an empty list stays an empty room; no list, no objects field', () => {
    expect(parseLightingScene(scene([]), 's').objects).toEqual([]);
    const { objects: _, ...noObjects } = scene([]);
    expect('objects' in parseLightingScene(noObjects, 's')).toBe(false);
  });

  it.each([
    [scene([{ mesh: 'a.obj', position: [1, 0, 1] }], { version: 1 }), 'scene.json: objects: needs "version": 2 (this file says version 1)'],
    [scene([{ mesh: 'a.obj', position: [1, 0, 1], yaww: 30 }]), "scene.json: objects[0].yaww: unknown field 'yaww' (did you mean 'yaw'?)"],
    [scene([{ mesh: 'a.obj', position: [1, 0, 1], scael: 2 }]), "scene.json: objects[0].scael: unknown field 'scael' (did you mean 'scale'?)"],
    [scene([{ meshh: 'a.obj', position: [1, 0, 1] }]), "scene.json: objects[0].meshh: unknown field 'meshh' (did you mean 'mesh'?)"],
    [scene([{ position: [1, 0, 1] }]), 'scene.json: objects[0].mesh: must be a path to an OBJ, glTF or GLB file'],
    [scene([{ mesh: 'chair.fbx', position: [1, 0, 1] }]), 'scene.json: objects[0].mesh: "chair.fbx" is not an .obj, .gltf or .glb file'],
    [scene([{ mesh: 'a.obj', position: [1, 0] }]), 'scene.json: objects[0].position: must be [x, y, z] in metres, got [1,0]'],
    [scene([{ mesh: 'a.obj', position: [1, 0, 1], scale: 0 }]), `scene.json: objects[0].scale: scale 0 is outside ${SCENE_LIMITS.minObjectScale}..${SCENE_LIMITS.maxObjectScale}`],
    [scene([{ mesh: 'a.obj', position: [1, 0, 1], reflectance: 1 }]), 'scene.json: objects[0].reflectance: reflectance 1 is outside [0, 1) (at 1 a closed room would never lose light)'],
    [scene([{ mesh: 'a.obj', position: [1, 0, 1], yaw: 'north' }]), 'scene.json: objects[0].yaw: must be a number, got "north"'],
    [scene({ mesh: 'a.obj' }), 'scene.json: objects: must be an array'],
  ])('refuses %j', (json, message) => {
    expect(refusal(json)).toBe(message);
  });

  it(`refuses more than ${SCENE_LIMITS.maxObjects} objects`, () => {
    const many = Array.from({ length: SCENE_LIMITS.maxObjects + 1 }, () => ({ mesh: 'a.obj', position: [1, 0, 1] }));
    expect(refusal(scene(many))).toBe(`scene.json: objects: more than ${SCENE_LIMITS.maxObjects} objects`);
  });
});
