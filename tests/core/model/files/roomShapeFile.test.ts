/** Scene file version 9 and share links with a room shape (issue 29), and the lighting scene a shaped configuration gives. */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../../src/core/catalog/defaultCatalog';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { lightingSceneJson } from '../../../../src/core/model/lightingScene/lightingSceneJson';
import { parseLightingScene } from '../../../../src/core/model/lightingScene/parseLightingScene';
import { wallFinishes } from '../../../../src/core/model/configuration/roomShape';
import { reflectanceRgb } from '../../../../src/core/model/lightingScene/reflectance';
import type { RoomShape } from '../../../../src/core/model/configuration/configuration';

const frozen = (name: string) => readFileSync(`tests/fixtures/formats/${name}`, 'utf8');

describe('a room shape in files', () => {
  const v9 = frozen('configuration-v9.luxbox.json');
  const config = deserializeConfiguration(v9, defaultCatalog);

  it('the frozen version-9 file keeps its shape, and a share link carries it', () => {
    expect(config.room.shape!.outline).toHaveLength(6);
    expect(config.room.shape!.slopes).toEqual([{ wall: 1, kneeHeight: 1.9, pitch: 35 }]);
    const again = decodeShareString(encodeShareString({ ...config, objects: config.objects.filter((o) => o.source.kind === 'library'), importedMeshes: {} }, defaultCatalog), defaultCatalog);
    expect(again.room).toEqual(config.room);
  });

  it('a shape in an older file is refused, naming the version the file says', () => {
    const v8 = JSON.parse(frozen('configuration-v8.luxbox.json'));
    v8.configuration.room.shape = JSON.parse(v9).configuration.room.shape;
    expect(() => deserializeConfiguration(JSON.stringify(v8), defaultCatalog, 'old.luxbox.json')).toThrow('old.luxbox.json: configuration.room.shape: needs "version": 9 (this file says version 8)');
    const v1 = JSON.parse(frozen('configuration-v1.luxbox.json'));
    v1.configuration.room.shape = v8.configuration.room.shape;
    expect(() => deserializeConfiguration(JSON.stringify(v1), defaultCatalog, 'old.luxbox.json')).toThrow('this file says version 1');
  });

  it('the file refuses a shape that breaks a rule, naming its path', () => {
    const doc = JSON.parse(v9);
    doc.configuration.room.shape.slopes[0].pitch = 0;
    expect(() => deserializeConfiguration(JSON.stringify(doc), defaultCatalog, 'a.json')).toThrow(/^a\.json: configuration\.room\.shape\.slopes\[0\]\.pitch: /);
    const moved = JSON.parse(v9);
    moved.configuration.room.shape.outline = (moved.configuration.room.shape as RoomShape).outline.map(([x, z]) => [x + 0.5, z]);
    expect(() => deserializeConfiguration(JSON.stringify(moved), defaultCatalog, 'a.json')).toThrow(
      "a.json: configuration.room.shape.outline: the outline spans x 0.5 to 5.5 m and z 0 to 4 m; it must span exactly 0 to the room's 5 m width and 0 to its 4 m depth",
    );
    const unknown = JSON.parse(v9);
    unknown.configuration.room.shape.roof = 'gable';
    expect(() => deserializeConfiguration(JSON.stringify(unknown), defaultCatalog, 'a.json')).toThrow("a.json: configuration.room.shape.roof: unknown field 'roof'");
  });

  it('toLightingScene: version 3 with the normalised room and each wall its finish; written and read back the same', () => {
    const scene = toLightingScene(config, defaultCatalog);
    expect(scene.version).toBe(3);
    const shape = scene.room.shape!;
    expect([scene.room.width, scene.room.depth]).toEqual([config.room.width, config.room.depth]);
    expect(shape.walls.map((w) => w.reflectance)).toEqual(wallFinishes({ ...config.room, shape: config.room.shape! }).map(reflectanceRgb));
    expect(shape.walls[2].reflectance).toEqual([0.6, 0.55, 0.5]);
    expect(shape.openings.map((o) => o.kind)).toEqual(['door', 'window']);
    const read = parseLightingScene(JSON.parse(JSON.stringify(lightingSceneJson(scene))), 'scene.json');
    expect(read.room.shape).toEqual(shape);
    expect(read.luminaires).toEqual(scene.luminaires.map((l) => expect.objectContaining({ position: l.position })));
    // Without its shape the same configuration stays the box of version 2 (it has objects), written exactly as before.
    const box = toLightingScene({ ...config, room: { ...config.room, shape: undefined } }, defaultCatalog);
    expect(box.version).toBe(2);
    expect('shape' in box.room).toBe(false);
    expect(serializeConfiguration({ ...config, room: (({ shape: _s, ...rest }) => rest)(config.room) }, defaultCatalog)).not.toContain('shape');
  });
});
