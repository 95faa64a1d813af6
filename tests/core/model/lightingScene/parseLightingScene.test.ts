/** Lighting scene v1 validation: every rule of docs/scene-format.md, one clear message naming the field. */
import { describe, expect, it } from 'vitest';
import { parseLightingScene, LightingSceneError } from '../../../../src/core/model/lightingScene/parseLightingScene';

const valid = () => ({
  version: 1,
  room: { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: [0.6, 0.5, 0.4] } },
  luminaires: [{ photometry: 'ies/downlight.ies', position: [2.5, 2.7, 2.0], yaw: 0, pitch: 0, roll: 0, dimming: 1.0, color: [1, 1, 1] }] as Record<string, unknown>[],
});
type Scene = ReturnType<typeof valid>;

describe('parseLightingScene', () => {
  it('accepts the docs/scene-format.md example and fills optional angles', () => {
    const s = valid();
    s.luminaires.push({ photometry: 'b.ldt', position: [0, 0, 0] });
    const scene = parseLightingScene(s, 'scene.json');
    expect(scene.luminaires[1]).toEqual({ photometry: 'b.ldt', position: [0, 0, 0], yaw: 0, pitch: 0, roll: 0 });
    expect(scene.room.reflectance.east).toEqual([0.6, 0.5, 0.4]);
  });

  it('accepts lamps on the boundary and the dimension limits', () => {
    const s = valid();
    s.room.width = 0.1;
    s.room.depth = 500;
    s.luminaires[0].position = [0.1, 2.8, 500];
    expect(() => parseLightingScene(s, 'scene.json')).not.toThrow();
  });

  const cases: [string, (s: Scene) => void, string][] = [
    ['lamp above the ceiling', (s) => s.luminaires.push({ photometry: 'a', position: [1, 2.9, 1] }), 'scene.json: luminaires[1].position[1]: 2.9 m is above the ceiling (height 2.8 m): luminaires must be inside the room'],
    ['lamp below the floor', (s) => (s.luminaires[0].position = [1, -0.01, 1]), 'scene.json: luminaires[0].position[1]: -0.01 m is below the floor (y = 0): luminaires must be inside the room'],
    ['lamp beyond the east wall', (s) => (s.luminaires[0].position = [5.2, 1, 1]), 'scene.json: luminaires[0].position[0]: 5.2 m is beyond the east wall (x = width 5 m): luminaires must be inside the room'],
    ['reflectance 1', (s) => (s.room.reflectance.north = 1), 'scene.json: room.reflectance.north: reflectance 1 is outside [0, 1) (at 1 a closed room would never lose light)'],
    ['negative RGB reflectance', (s) => (s.room.reflectance.east = [0.5, -0.1, 0.2]), 'scene.json: room.reflectance.east[1]: reflectance -0.1 is outside [0, 1) (at 1 a closed room would never lose light)'],
    ['missing surface', (s) => delete (s.room.reflectance as Partial<Scene['room']['reflectance']>).west, 'scene.json: room.reflectance.west: is missing'],
    ['room too small', (s) => (s.room.height = 0.05), 'scene.json: room.height: 0.05 m is outside 0.1..500 m'],
    ['room too large', (s) => (s.room.width = 501), 'scene.json: room.width: 501 m is outside 0.1..500 m'],
    ['a string dimension', (s) => ((s.room as Record<string, unknown>).depth = '4'), 'scene.json: room.depth: must be a number, got "4"'],
    ['newer version', (s) => ((s as Record<string, unknown>).version = 4), 'scene.json: version: made by a newer luxbox (version 4; this one reads versions 1 to 3)'],
    ['wrong version', (s) => ((s as Record<string, unknown>).version = '1'), 'scene.json: version: unsupported version "1" (this program reads versions 1 to 3)'],
    ['dimming above 1', (s) => (s.luminaires[0].dimming = 1.5), 'scene.json: luminaires[0].dimming: dimming 1.5 is outside 0..1'],
    ['short position', (s) => (s.luminaires[0].position = [1, 2]), 'scene.json: luminaires[0].position: must be [x, y, z] in metres, got [1,2]'],
    ['no photometry', (s) => delete s.luminaires[0].photometry, 'scene.json: luminaires[0].photometry: must be a path to an IES or LDT file'],
    ['negative colour', (s) => (s.luminaires[0].color = [1, -1, 1]), 'scene.json: luminaires[0].color: colour components must lie in 0..100'],
  ];
  for (const [name, mutate, message] of cases) {
    it(`rejects ${name}`, () => {
      const s = valid();
      mutate(s);
      expect(() => parseLightingScene(s, 'scene.json')).toThrow(LightingSceneError);
      expect(() => parseLightingScene(s, 'scene.json')).toThrow(message);
    });
  }

  it('rejects non-objects', () => {
    expect(() => parseLightingScene(null, 'x.json')).toThrow('x.json: a lighting scene must be a JSON object');
    expect(() => parseLightingScene([1], 'x.json')).toThrow('x.json: a lighting scene must be a JSON object');
  });
});
