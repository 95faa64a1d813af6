/** Lighting scene version 3 (issue 29): a room of any shape, read and written; every refusal names its path. */
import { describe, expect, it } from 'vitest';
import { parseLightingScene } from '../../../../src/core/model/lightingScene/parseLightingScene';
import { lightingSceneJson } from '../../../../src/core/model/lightingScene/lightingSceneJson';
import { nearestBoxWall } from '../../../../src/core/model/lightingScene/boxWallFacing';
import { normaliseRoom } from '../../../../src/core/room/normaliseRoom';
import type { RoomInput } from '../../../../src/core/room/roomInput';

interface RoomJson {
  outline: unknown[];
  height: unknown;
  slopes: Record<string, unknown>[];
  reflectance: Record<string, unknown>;
  openings: Record<string, unknown>[];
  [field: string]: unknown;
}

/** The contract example, with a lamp in the L's main wing and a table in the other. */
const example = () => ({
  version: 3,
  room: {
    outline: [
      [0, 0],
      [6, 0],
      [6, 3],
      [3.5, 3],
      [3.5, 5],
      [0, 5],
    ] as unknown[],
    height: 2.6,
    slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40 }] as Record<string, unknown>[],
    reflectance: { floor: 0.25, ceiling: 0.8, walls: 0.5 } as Record<string, unknown>,
    openings: [{ wall: 4, offset: 0.8, width: 0.9, sill: 0, height: 2.0, kind: 'door' }] as Record<string, unknown>[],
  } as RoomJson,
  luminaires: [{ photometry: 'ies/downlight.ies', position: [2, 2.4, 3.5], yaw: 0, pitch: 0, roll: 0 }] as Record<string, unknown>[],
  objects: [{ mesh: 'table.obj', position: [1.5, 0, 4] }] as Record<string, unknown>[],
});
type Scene = ReturnType<typeof example>;

describe('lighting scene version 3', () => {
  it('reads the issue example: the normalised shape, the bounding box and the box record of finishes', () => {
    const s = example();
    const scene = parseLightingScene(s, 'scene.json');
    expect(scene.version).toBe(3);
    expect(scene.room.shape).toEqual(normaliseRoom(s.room as unknown as RoomInput));
    expect([scene.room.width, scene.room.height, scene.room.depth]).toEqual([6, 2.6, 5]);
    expect(scene.room.reflectance).toEqual({ floor: 0.25, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 });
    expect(scene.luminaires[0]).toEqual({ photometry: 'ies/downlight.ies', position: [2, 2.4, 3.5], yaw: 0, pitch: 0, roll: 0 });
    expect(scene.objects).toEqual([{ mesh: 'table.obj', position: [1.5, 0, 4], yaw: 0, scale: 1 }]);
  });

  it('fills north, east, south, west from the wall that faces most nearly that way (per-wall list, RGB, either orientation)', () => {
    const s = example();
    // Walls 0..5: north (z = 0) 0.1, east (x = 6) 0.2, the notch's south-facing 0.3, its east-facing 0.4, the south (z = 5) 0.45, west 0.6.
    s.room.reflectance = { floor: [0.3, 0.2, 0.1], ceiling: 0.8, walls: [0.1, 0.2, 0.3, [0.4, 0.4, 0.5], 0.45, 0.6] };
    const r = parseLightingScene(s, 'scene.json').room.reflectance;
    // Two walls face south (wall 2, 2.5 m; wall 4, 3.5 m): the longer one; two face east (wall 1, 3 m; wall 3, 2 m): the longer.
    expect(r).toEqual({ floor: [0.3, 0.2, 0.1], ceiling: 0.8, north: 0.1, east: 0.2, south: 0.45, west: 0.6 });
    // The same room written the other way round reads the same finishes per wall.
    const turned = example();
    turned.room.outline = [...(s.room.outline as unknown[])].reverse();
    // Reversed, input wall j is the old wall 4 − j (mod 6): the list follows.
    const old = s.room.reflectance.walls as unknown[];
    turned.room.reflectance = { ...(s.room.reflectance as object), walls: [4, 3, 2, 1, 0, 5].map((k) => old[k]) };
    turned.room.slopes = [{ wall: 4, kneeHeight: 1.2, pitch: 40 }];
    turned.room.openings = [{ wall: 0, offset: 2 - 0.8 - 0.9, width: 0.9, sill: 0, height: 2, kind: 'door' }];
    const t = parseLightingScene(turned, 'scene.json');
    expect(t.room.reflectance).toEqual(r);
    expect(t.room.shape!.ceilingPlanes).toEqual(parseLightingScene(s, 'scene.json').room.shape!.ceilingPlanes.map((p) => expect.objectContaining({ c: expect.closeTo(p.c, 12), gx: expect.closeTo(p.gx, 12), gz: expect.closeTo(p.gz, 12) })));
  });

  it('the box walls by inward normal, a 45° wall going to the earlier name', () => {
    expect(nearestBoxWall([0, 1])).toBe('north');
    expect(nearestBoxWall([-1, 0])).toBe('east');
    expect(nearestBoxWall([0.2, -0.98])).toBe('south');
    expect(nearestBoxWall([0.9, 0.1])).toBe('west');
    expect(nearestBoxWall([Math.SQRT1_2, Math.SQRT1_2])).toBe('north');
  });

  it('writes back what it read: the room object as the author gave it, for every field', () => {
    const s = example();
    s.room.slopes = [
      { wall: 0, kneeHeight: 1.2, pitch: 40, reflectance: [0.7, 0.7, 0.6] },
      { wall: 5, kneeHeight: 2, pitch: 30 },
    ];
    s.room.reflectance = {
      floor: 0.25,
      ceiling: 0.8,
      walls: [
        [0.1, 0.1, 0.1],
        [0.2, 0.2, 0.2],
        [0.3, 0.3, 0.3],
        [0.4, 0.4, 0.5],
        [0.45, 0.45, 0.45],
        [0.6, 0.6, 0.6],
      ],
    };
    s.room.openings = [
      { wall: 4, offset: 0.8, width: 0.9, sill: 0, height: 2, kind: 'door' },
      { wall: 1, offset: 1.5, width: 1.2, sill: 0.9, height: 1.2, kind: 'window' },
      { wall: 2, offset: 1, width: 1, sill: 0, height: 2.1, kind: 'opening' },
    ];
    const scene = parseLightingScene(s, 'scene.json');
    const written = JSON.parse(JSON.stringify(lightingSceneJson(scene)));
    expect(written.room).toEqual({ ...s.room, reflectance: { ...(s.room.reflectance as object), walls: [0.1, 0.2, 0.3, [0.4, 0.4, 0.5], 0.45, 0.6].map((v) => (typeof v === 'number' ? [v, v, v] : v)) } });
    expect(Object.keys(written.room)).toEqual(['outline', 'height', 'slopes', 'reflectance', 'openings']);
    expect(parseLightingScene(written, 'again.json')).toEqual(scene);
    // Either orientation: the clockwise outline comes back clockwise, its offsets as written.
    const cw = example();
    cw.room.outline = [...(s.room.outline as unknown[])].reverse();
    cw.room.slopes = [{ wall: 4, kneeHeight: 1.2, pitch: 40 }];
    cw.room.openings = [{ wall: 0, offset: 0.3, width: 0.9, sill: 0, height: 2, kind: 'door' }];
    const back = JSON.parse(JSON.stringify(lightingSceneJson(parseLightingScene(cw, 'cw.json'))));
    expect(back.room).toEqual(cw.room);
  });

  it('a version-1/2 scene writes as it is', () => {
    const box = { version: 1, room: { width: 4, height: 2.5, depth: 3, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } }, luminaires: [] };
    const scene = parseLightingScene(box, 'box.json');
    expect(scene.room.shape).toBeUndefined();
    expect(lightingSceneJson(scene)).toBe(scene);
  });

  const refusals: [string, (s: Scene) => void, string][] = [
    ['an unknown room field', (s) => (s.room.sheen = 'satin'), "scene.json: room.sheen: unknown field 'sheen'"],
    ['a misspelt slope field', (s) => (s.room.slopes[0].knee = 1), "scene.json: room.slopes[0].knee: unknown field 'knee'"],
    ['an unknown opening field', (s) => (s.room.openings[0].glass = true), "scene.json: room.openings[0].glass: unknown field 'glass'"],
    ['a box field in version 3', (s) => (s.room.width = 6), 'scene.json: room.width: a version-3 room has an outline instead of width and depth (or say "version": 2 for a box)'],
    ['an outline in version 2', (s) => (s.version = 2), 'scene.json: room.outline: needs "version": 3 (this file says version 2)'],
    ['no outline', (s) => delete (s.room as Partial<RoomJson>).outline, 'scene.json: room.outline: is missing'],
    [
      'two corners',
      (s) =>
        (s.room.outline = [
          [0, 0],
          [1, 0],
        ]),
      'scene.json: room.outline: needs at least 3 corners',
    ],
    ['a corner of three numbers', (s) => (s.room.outline[2] = [6, 3, 1]), 'scene.json: room.outline[2]: must be [x, z] in metres, got [6,3,1]'],
    ['a short wall', (s) => (s.room.outline[2] = [6, 0.05]), 'scene.json: room.outline[1]: wall 1 (corner 1 to corner 2) is 0.05 m long; each wall must be at least 0.1 m'],
    [
      'a crossing outline',
      (s) =>
        (s.room.outline = [
          [0, 0],
          [4, 0],
          [0, 4],
          [4, 4],
        ]),
      'scene.json: room.outline[3]: wall 1 and wall 3 cross or touch; the outline must not intersect itself',
    ],
    ['a flat ceiling too low', (s) => (s.room.height = 0.05), 'scene.json: room.height: 0.05 m is outside 0.1..500 m'],
    ['a slope on no wall', (s) => (s.room.slopes[0].wall = 6), 'scene.json: room.slopes[0].wall: slope 0 stands on wall 6, but the room has walls 0 to 5'],
    ['a pitch of 90°', (s) => (s.room.slopes[0].pitch = 90), 'scene.json: room.slopes[0].pitch: 90° is not between 0° and 90°'],
    ['a knee above the ceiling', (s) => (s.room.slopes[0].kneeHeight = 3), 'scene.json: room.slopes[0].kneeHeight: slope 0 has a knee height of 3 m; it must lie between 0 and the ceiling height 2.6 m'],
    ['an opening past its wall', (s) => (s.room.openings[0].offset = 3), "scene.json: room.openings[0].offset: opening 0 reaches from 3 to 3.9 m along wall 4, which is 3.5 m long; it must stay between the wall's ends"],
    ['a kind of opening', (s) => (s.room.openings[0].kind = 'hatch'), 'scene.json: room.openings[0].kind: must be "door", "window" or "opening", got "hatch"'],
    ['an opening above the wall', (s) => (s.room.openings[0].height = 2.7), 'scene.json: room.openings[0].height: opening 0 reaches 2.7 m up wall 4, above its top (2.6 m there)'],
    ['one reflectance short', (s) => (s.room.reflectance.walls = [0.5, 0.5, 0.5, 0.5, 0.5]), "scene.json: room.reflectance.walls: the walls' reflectances list 5 entries for 6 walls"],
    ['a wall reflectance of 1', (s) => (s.room.reflectance.walls = 1), 'scene.json: room.reflectance.walls: reflectance 1 is outside [0, 1) (at 1 a closed room would never lose light)'],
    ['a lamp in the notch of the L', (s) => (s.luminaires[0].position = [5, 2, 4]), "scene.json: luminaires[0].position: (5, 4) in plan is outside the room's outline: luminaires must be inside the room"],
    ['a lamp above the slope', (s) => (s.luminaires[0].position = [2, 2, 0.5]), 'scene.json: luminaires[0].position: 2 m is above slope 0 (1.62 m there): luminaires must be inside the room'],
    ['a lamp above the flat ceiling', (s) => (s.luminaires[0].position = [2, 2.7, 4]), 'scene.json: luminaires[0].position: 2.7 m is above the ceiling (2.6 m): luminaires must be inside the room'],
    ['a lamp below the floor', (s) => (s.luminaires[0].position = [2, -0.1, 4]), 'scene.json: luminaires[0].position: -0.1 m is below the floor: luminaires must be inside the room'],
    ['an object in the notch', (s) => (s.objects[0].position = [4.5, 0, 4.5]), "scene.json: objects[0].position: (4.5, 4.5) in plan is outside the room's outline: objects must be inside the room"],
  ];
  for (const [what, change, message] of refusals) {
    it(`refuses ${what}`, () => {
      const s = example();
      change(s);
      expect(() => parseLightingScene(s, 'scene.json')).toThrow(message);
      try {
        parseLightingScene(s, 'scene.json');
      } catch (e) {
        expect((e as Error).message).toBe(message);
      }
    });
  }
});
