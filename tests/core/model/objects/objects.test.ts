import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { boxPart, composeParts, frustumPart } from '../../../../src/core/model/objects/furniture/meshParts';
import { objectMesh, objectPlacement, placedBounds, sourceMesh } from '../../../../src/core/model/objects/objectGeometry';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString, encodeShareLink, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { SceneFileError } from '../../../../src/core/model/files/sceneFileError';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import type { TriangleMesh } from '../../../../src/core/mesh/triangleMesh';
import { catalog, run } from '../helpers';

const room = () => createConfiguration({ width: 5, depth: 4, height: 2.8 });
const grey = (): [number, number, number] => [0.5, 0.5, 0.5];
/** A 1 × 0.5 × 1 m block with its origin at the centre of its bottom. */
const block = (): TriangleMesh => composeParts([boxPart('body', [-0.5, 0, -0.5], [0.5, 0.5, 0.5])], grey);

/** The refusal of an action, asserting that performing it anyway throws or breaks validate() (the always-valid contract). */
function refusal(state: Configuration, name: string, params: unknown): string {
  const a = bindAction(name, params, catalog);
  const e = a.isEnabled(state);
  if (e === true) throw new Error(`${name} was enabled`);
  let broken: Configuration | null = null;
  try {
    broken = a.perform(state);
  } catch {
    /* refused by perform: fine */
  }
  if (broken) expect(validate(broken, catalog).length).toBeGreaterThan(0);
  return e.reason;
}

describe('object actions', () => {
  it('adds a library item where asked, with an id from the counter', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 2.5, z: 2 } });
    expect(s.objects).toEqual([{ id: 'o1', source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 2.5, z: 2 }, yaw: 0, scale: 1, finishes: {} }]);
    expect(s.nextId).toBe(2);
    expect(validate(s, catalog)).toEqual([]);
  });

  it('moves a new object to the nearest spot inside the room (exact for the rotated mesh)', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'sofa' }, placement: { on: 'floor', x: 0.2, z: 3.9 } });
    // 2.1 × 0.9 m: pushed to x = 1.05 (west wall) and z = 4 − 0.45 (south wall)
    const p = s.objects[0].placement as { x: number; z: number };
    expect(p.x).toBeCloseTo(1.05, 6);
    expect(p.z).toBeCloseTo(3.55, 6);
    const turned = run(room(), 'addObject', { source: { kind: 'library', item: 'sofa' }, placement: { on: 'floor', x: 0.2, z: 2 }, yaw: 90 });
    expect((turned.objects[0].placement as { x: number }).x).toBeCloseTo(0.45, 6); // turned, its 0.9 m depth runs along x
    expect(refusal(createConfiguration({ width: 1.5, depth: 4, height: 2.8 }), 'addObject', { source: { kind: 'library', item: 'dining-table' } })).toMatch(/does not fit in this 1.5 m room/);
  });

  it('refuses moves through a wall and turns that would not fit, with the wall named', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'dining-table' } });
    expect(refusal(s, 'moveObject', { objectId: 'o1', placement: { on: 'floor', x: 0.5, z: 2 } })).toMatch(/cannot move it there: Dining table passes through the west wall/);
    expect(run(s, 'moveObject', { objectId: 'o1', placement: { on: 'floor', x: 0.9, z: 2 } }).objects[0].placement).toEqual({ on: 'floor', x: 0.9, z: 2 });
    // a 2.1 m sofa in a 2.15 m wide room: turned by 30° it spans 2.1 cos 30° + 0.9 sin 30° = 2.27 m
    const narrow = run(createConfiguration({ width: 2.15, depth: 4, height: 2.8 }), 'addObject', { source: { kind: 'library', item: 'sofa' } });
    expect(refusal(narrow, 'rotateObject', { objectId: 'o1', by: 30 })).toMatch(/cannot turn it here: .*passes through the west wall and the east wall/);
    const at45 = run(narrow, 'rotateObject', { objectId: 'o1', by: 45 }); // (2.1 + 0.9)/√2 = 2.12 m fits
    expect(at45.objects[0].yaw).toBe(45);
    expect(run(at45, 'rotateObject', { objectId: 'o1', by: -90 }).objects[0].yaw).toBe(315);
  });

  it('checks the placed vertices, not a rotated bounding box', () => {
    // A round table of radius 0.5 (64 segments) turned by 45° with its centre 0.501 m from the west wall fits:
    // its rotated local box would reach 0.707 m, its vertices reach 0.5 m.
    const disc = composeParts([frustumPart('top', 0, 0, 0, 0.75, 0.5, 0.5, 64)], grey);
    const s = run(room(), 'addObject', { source: { kind: 'import', name: 'round.obj', mesh: disc, units: 'm' }, placement: { on: 'floor', x: 0.501, z: 2 }, yaw: 45 });
    expect(s.objects[0].placement).toEqual({ on: 'floor', x: 0.501, z: 2 });
    const b = placedBounds(s.objects[0], sourceMesh(s, s.objects[0].source)!, s.room);
    expect(b.min[0]).toBeGreaterThan(0);
    expect(b.min[0]).toBeLessThan(0.002);
  });

  it('resizes within the stated limits, and refuses a size that leaves the room', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'open-shelf' } });
    expect(refusal(s, 'resizeObject', { objectId: 'o1', scale: 2.5 })).toMatch(/scale must be between 0.5 and 2 for library furniture/);
    expect(refusal(s, 'resizeObject', { objectId: 'o1', scale: 1.5 })).toMatch(/reaches 3 m, above the 2.8 m ceiling/); // 2 m × 1.5
    expect(run(s, 'resizeObject', { objectId: 'o1', scale: 1.4 }).objects[0].scale).toBe(1.4);
  });

  it('refinishes materials with finish ids or RGB; objectMesh applies them and keeps the rest', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'dining-table' } });
    expect(refusal(s, 'refinishObject', { objectId: 'o1', material: 'cushions', finish: 'oak-veneer' })).toMatch(/has no material 'cushions' \(it has: top, legs\)/);
    expect(refusal(s, 'refinishObject', { objectId: 'o1', material: 'top', finish: 'gold' })).toMatch(/unknown finish 'gold'/);
    expect(refusal(s, 'refinishObject', { objectId: 'o1', material: 'top', finish: [0.5, 0.97, 0.5] })).toMatch(/outside \[0, 0.95\]/);
    const t = run(run(s, 'refinishObject', { objectId: 'o1', material: 'top', finish: 'white-lacquer' }), 'refinishObject', { objectId: 'o1', material: 'legs', finish: [0.1, 0.2, 0.3] });
    const mesh = objectMesh(t, 'o1');
    expect(mesh.materials).toEqual([
      { name: 'top', reflectance: [0.8, 0.8, 0.8] },
      { name: 'legs', reflectance: [0.1, 0.2, 0.3] },
    ]);
    expect(mesh.positions).toBe(sourceMesh(t, t.objects[0].source)!.positions); // shared, not copied
    expect(objectMesh(run(t, 'refinishObject', { objectId: 'o1', material: 'top', finish: null }), 'o1').materials[0].reflectance).toEqual([0.493, 0.327, 0.158]);
  });

  it('hangs wall items on their wall, facing into the room', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'picture' } });
    expect(s.objects[0].placement).toEqual({ on: 'wall', wall: 'north', u: 2.5, y: 1.55 });
    const frames = [
      ['north', [1, 1.5, 0], 0],
      ['south', [1, 1.5, 4], 180],
      ['west', [0, 1.5, 1], 90],
      ['east', [5, 1.5, 1], 270],
    ] as const;
    for (const [wall, position, yaw] of frames) {
      const t = run(s, 'moveObject', { objectId: 'o1', placement: { on: 'wall', wall, u: 1, y: 1.5 } });
      const pl = objectPlacement(t.objects[0], t.room);
      expect(pl.position).toEqual(position);
      expect(pl.yaw).toBe(yaw);
      // 3 cm deep, all of it inside the room and touching its wall
      const b = placedBounds(t.objects[0], sourceMesh(t, t.objects[0].source)!, t.room);
      const across = wall === 'north' || wall === 'south' ? 2 : 0;
      const wallCoord = wall === 'north' || wall === 'west' ? 0 : wall === 'south' ? 4 : 5;
      expect(Math.min(Math.abs(b.min[across] - wallCoord), Math.abs(b.max[across] - wallCoord))).toBeLessThan(1e-6);
      expect(b.max[across] - b.min[across]).toBeCloseTo(0.03, 6);
    }
    expect(refusal(s, 'moveObject', { objectId: 'o1', placement: { on: 'wall', wall: 'east', u: 3.8, y: 1.5 } })).toMatch(/passes through the south wall/);
    expect(refusal(s, 'moveObject', { objectId: 'o1', placement: { on: 'wall', wall: 'north', u: 2, y: 2.6 } })).toMatch(/above the 2.8 m ceiling/);
    expect(refusal(s, 'moveObject', { objectId: 'o1', placement: { on: 'floor', x: 2, z: 2 } })).toMatch(/a Framed picture goes on a wall/);
    expect(refusal(s, 'rotateObject', { objectId: 'o1', by: 90 })).toMatch(/does not turn/);
  });

  it('shares an imported mesh between its objects and drops it with the last one', () => {
    const mesh = block();
    let s = run(room(), 'addObject', { source: { kind: 'import', name: 'block.obj', mesh, units: 'cm' } });
    expect(Object.keys(s.importedMeshes)).toEqual(['i1']);
    expect(s.importedMeshes.i1).toEqual({ name: 'block.obj', mesh, units: 'cm' });
    expect(s.objects[0].source).toEqual({ kind: 'imported', mesh: 'i1' });
    s = run(s, 'addObject', { source: { kind: 'imported', mesh: 'i1' }, placement: { on: 'floor', x: 1, z: 1 } });
    expect(s.objects.map((o) => o.id)).toEqual(['o2', 'o3']);
    expect(refusal(s, 'resizeObject', { objectId: 'o2', scale: 4.5 })).toMatch(/between 0.25 and 4 for imported models/);
    expect(run(s, 'resizeObject', { objectId: 'o2', scale: 0.25 }).objects[0].scale).toBe(0.25);
    s = run(s, 'removeObject', { objectId: 'o2' });
    expect(Object.keys(s.importedMeshes)).toEqual(['i1']);
    s = run(s, 'removeObject', { objectId: 'o3' });
    expect(s.importedMeshes).toEqual({});
    expect(validate(s, catalog)).toEqual([]);
  });

  it('refuses malformed imported meshes and meshes that reach below their origin', () => {
    const bad = { ...block(), indices: new Uint32Array([0, 1, 99]), materialOfTriangle: new Uint16Array(1) };
    expect(refusal(room(), 'addObject', { source: { kind: 'import', name: 'bad.obj', mesh: bad, units: 'm' } })).toMatch(/imported model 'bad.obj': indices\[2\] = 99 is past the last vertex \(7\)/);
    const sunk = composeParts([boxPart('body', [-0.5, -0.1, -0.5], [0.5, 0.5, 0.5])], grey);
    expect(refusal(room(), 'addObject', { source: { kind: 'import', name: 'sunk.obj', mesh: sunk, units: 'm' } })).toMatch(/does not fit between floor and ceiling/);
    expect(refusal(room(), 'addObject', { source: { kind: 'library', item: 'spaceship' } })).toMatch(/no furniture item 'spaceship'/);
    expect(refusal(room(), 'addObject', { source: { kind: 'imported', mesh: 'i9' } })).toMatch(/no imported mesh 'i9'/);
  });
});

describe('objects in the lighting scene', () => {
  it('is version 1 without objects and version 2 with them, one entry per object', () => {
    expect(toLightingScene(room(), catalog).version).toBe(1);
    let s = run(room(), 'addObject', { source: { kind: 'library', item: 'sofa' }, placement: { on: 'floor', x: 2, z: 2 }, yaw: 90 });
    s = run(s, 'resizeObject', { objectId: 'o1', scale: 1.1 });
    s = run(s, 'addObject', { source: { kind: 'library', item: 'picture' }, placement: { on: 'wall', wall: 'east', u: 2, y: 1.6 } });
    const scene = toLightingScene(s, catalog);
    expect(scene.version).toBe(2);
    expect(scene.objects).toEqual([
      { mesh: 'object:o1', position: [2, 0, 2], yaw: 90, scale: 1.1, id: 'o1' },
      { mesh: 'object:o2', position: [5, 1.6, 2], yaw: 270, scale: 1, id: 'o2' },
    ]);
  });
});

describe('objects in scene files and share links', () => {
  const furnished = () => {
    let s = run(room(), 'addObject', { source: { kind: 'library', item: 'dining-table' } });
    s = run(s, 'refinishObject', { objectId: 'o1', material: 'top', finish: [0.3, 0.2, 0.1] });
    s = run(s, 'addObject', { source: { kind: 'import', name: 'kitchen.obj', mesh: block(), units: 'mm' }, placement: { on: 'floor', x: 1, z: 1 }, yaw: 30 });
    return run(s, 'addObject', { source: { kind: 'library', item: 'picture' } });
  };

  it('round-trips objects and imported meshes (base64 typed arrays) through a version 5 file', () => {
    const s = furnished();
    const text = serializeConfiguration(s, catalog);
    const file = JSON.parse(text);
    expect(file.version).toBe(SCENE_FILE_VERSION);
    expect(typeof file.configuration.importedMeshes.i2.positions).toBe('string');
    // 8 vertices × 3 Float32 = 96 bytes → 128 base64 characters
    expect(file.configuration.importedMeshes.i2.positions.length).toBe(128);
    const back = deserializeConfiguration(text, catalog);
    expect(back).toEqual(s);
    expect(back.importedMeshes.i2.mesh.positions).toEqual(s.importedMeshes.i2.mesh.positions);
  });

  it('refuses objects in older versions and bad object fields, naming the field', () => {
    const file = JSON.parse(serializeConfiguration(furnished(), catalog));
    const read = (f: unknown) => () => deserializeConfiguration(JSON.stringify(f), catalog);
    expect(read({ ...file, version: 2 })).toThrow('scene file: configuration.objects: needs "version": 3 (this file says version 2)');
    expect(read({ ...file, version: 1 })).toThrow('scene file: configuration.objects: needs "version": 3 (this file says version 1)');
    /** The parsed file's configuration, loosely typed: the edits below break it on purpose. */
    interface Loose {
      objects: { id: string; scael?: number; placement: { on: string; x?: number }; finishes: Record<string, unknown> }[];
      importedMeshes: Record<string, { positions: string; indices: string; materialOfTriangle: string }>;
    }
    const edit = (f: (c: Loose) => void) => {
      const copy = JSON.parse(JSON.stringify(file));
      f(copy.configuration);
      return copy;
    };
    expect(read(edit((c) => (c.objects[0].scael = 1)))).toThrow(/configuration\.objects\[0\]\.scael: unknown field 'scael'/);
    expect(read(edit((c) => (c.objects[0].placement.on = 'ceiling')))).toThrow(/configuration\.objects\[0\]\.placement\.on/);
    expect(read(edit((c) => (c.objects[0].finishes.top = 'gold')))).toThrow(/configuration\.objects\[0\]\.finishes\.top: unknown finish 'gold'/);
    expect(read(edit((c) => (c.importedMeshes.i2.positions = 'not base64!')))).toThrow(/configuration\.importedMeshes\.i2\.positions: is not base64/);
    expect(read(edit((c) => (c.importedMeshes.i2.materialOfTriangle = 'AA==')))).toThrow(/configuration\.importedMeshes\.i2\.materialOfTriangle: holds 1 bytes, not a whole number of 2-byte values/);
    expect(read(edit((c) => (c.importedMeshes.i2.indices = 'AAAAAA==')))).toThrow(/configuration\.importedMeshes\.i2\.mesh: imported model 'kitchen.obj': indices hold 1 numbers/);
    expect(read(edit((c) => (c.objects[1].placement.x = -1)))).toThrow(/configuration\.objects\[1\]\.placement: kitchen.obj passes through the west wall/);
    expect(read(edit((c) => (c.objects = c.objects.filter((o) => o.id !== 'o3'))))).toThrow(/configuration\.importedMeshes\.i2: imported model 'kitchen.obj' \(i2\) is used by no object/);
  });

  it('share links carry library objects and report the imported ones they leave out', () => {
    const s = furnished();
    const link = encodeShareLink(s, catalog);
    expect(link.leftOut).toEqual([{ objectId: 'o3', name: 'kitchen.obj' }]);
    expect(link.notice).toBe("the imported model 'kitchen.obj' is not in the link; save the file to keep it");
    const back = decodeShareString(link.text, catalog);
    expect(back.objects.map((o) => o.id)).toEqual(['o1', 'o4']);
    expect(back.objects[0].finishes).toEqual({ top: [0.3, 0.2, 0.1] });
    expect(back.importedMeshes).toEqual({});
    expect(() => encodeShareString(s, catalog)).toThrow(SceneFileError);
    const libraryOnly = run(s, 'removeObject', { objectId: 'o3' });
    expect(encodeShareLink(libraryOnly, catalog).notice).toBeNull();
    expect(decodeShareString(encodeShareString(libraryOnly, catalog), catalog)).toEqual(libraryOnly);
  });
});
