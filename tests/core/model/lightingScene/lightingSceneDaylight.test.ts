/**
 * The daylight contract hooked into the lighting-scene reader (issue 30, docs/daylight.md "The
 * contract"): version-2 windows become window openings of the box's outline, version-3 window
 * openings carry `transmittance`, and `sky` is read for both; the refusals name their path.
 */
import { describe, expect, it } from 'vitest';
import { lightingSceneJson } from '../../../../src/core/model/lightingScene/lightingSceneJson';
import { parseLightingScene } from '../../../../src/core/model/lightingScene/parseLightingScene';
import { roomSurfaces } from '../../../../src/core/room/roomSurfaces';

const v2 = (extra: Record<string, unknown>) => ({
  version: 2,
  room: { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
  luminaires: [],
  ...extra,
});
const v3 = (openings: unknown[], extra: Record<string, unknown> = {}) => ({
  version: 3,
  room: {
    outline: [
      [0, 0],
      [5, 0],
      [5, 4],
      [0, 4],
    ],
    height: 2.8,
    openings,
    reflectance: { floor: 0.2, ceiling: 0.8, walls: 0.5 },
  },
  luminaires: [],
  ...extra,
});
const refusal = (json: unknown): string => {
  try {
    parseLightingScene(json, 'scene.json');
  } catch (error) {
    return (error as Error).message;
  }
  throw new Error('accepted');
};

describe('lighting scenes with daylight', () => {
  it('version 2: a south window becomes the box outline’s window opening at the same world rectangle, with its glazing and the sky', () => {
    const s = parseLightingScene(v2({ windows: [{ wall: 'south', u: 1, v: 0.9, width: 1.5, height: 1.4, transmittance: 'triple' }], sky: { type: 'cie-overcast', horizontalIlluminance: 12000 } }), 'scene.json');
    expect(s.version).toBe(2);
    expect(s.room.width).toBe(5);
    const window = roomSurfaces(s.room.shape!)
      .flatMap((f) => f.openings)
      .find((o) => o.kind === 'window')!;
    // u runs along x on the south wall (z = 4): x 1 … 2.5, y 0.9 … 2.3.
    const xs = window.polygon.map((p) => p[0]);
    const ys = window.polygon.map((p) => p[1]);
    expect([Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)]).toEqual([1, 2.5, 0.9, 2.3].map((v) => expect.closeTo(v, 12)));
    expect(window.polygon.every((p) => p[2] === 4)).toBe(true);
    expect(s.daylight?.transmittance[window.inputIndex]).toBe('triple');
    expect(s.daylight?.sky).toEqual({ type: 'cie-overcast', horizontalIlluminance: 12000, groundReflectance: 0.2 });
  });

  it('version 2: a sky without windows keeps the box; windows without a sky are openings (they let light out)', () => {
    const skyOnly = parseLightingScene(v2({ sky: { type: 'uniform' } }), 's');
    expect(skyOnly.room.shape).toBeUndefined();
    expect(skyOnly.daylight?.sky?.type).toBe('uniform');
    const dark = parseLightingScene(v2({ windows: [{ wall: 'west', u: 1, v: 1, width: 1, height: 1 }] }), 's');
    expect(dark.room.shape?.openings).toHaveLength(1);
    expect(dark.daylight?.sky).toBeUndefined();
  });

  it('version 3: transmittance on a window (default "double"), the sky and the sun', () => {
    const s = parseLightingScene(
      v3(
        [
          { wall: 2, offset: 1, width: 1.5, sill: 0.9, height: 1.4, kind: 'window', transmittance: 0.6 },
          { wall: 0, offset: 1, width: 1, sill: 0, height: 2, kind: 'door' },
          { wall: 1, offset: 1, width: 1, sill: 1, height: 1, kind: 'window' },
        ],
        {
          sky: { type: 'cie-clear', sun: { city: 'Zurich', date: '2026-06-21', time: '10:00', timeZone: '+02:00' } },
        },
      ),
      's',
    );
    // Only what is written; the window without one is "double" when baked.
    expect(s.daylight?.transmittance).toEqual({ 0: 0.6 });
    expect(s.daylight?.sky?.sun?.city).toBe('Zurich');
    expect(s.room.shape?.openings).toHaveLength(3);
  });

  it('writes back what it read: version 2 as the box with its windows and sky, version 3 with transmittance on its openings', () => {
    const two = v2({
      windows: [{ wall: 'east', u: 0.5, v: 1, width: 1.2, height: 1, transmittance: 0.7 }],
      sky: { type: 'cie-clear', horizontalIlluminance: 20000, groundReflectance: 0.3, sun: { city: 'Zurich', timeZone: '+02:00', date: '2026-06-21', time: '10:00' } },
    });
    const parsed2 = parseLightingScene(two, 's');
    const written2 = JSON.parse(JSON.stringify(lightingSceneJson(parsed2)));
    expect(written2.version).toBe(2);
    expect(written2.room).toEqual(two.room);
    const given = two as unknown as { windows: unknown; sky: { sun: object } };
    expect(written2.windows).toEqual(given.windows);
    expect(written2.sky).toEqual({ ...given.sky, sun: { ...given.sky.sun, time: '10:00:00' } });
    expect(parseLightingScene(written2, 'again.json')).toEqual(parsed2);
    const three = v3(
      [
        { wall: 2, offset: 1, width: 1.5, sill: 0.9, height: 1.4, kind: 'window', transmittance: 'single' },
        { wall: 1, offset: 1, width: 1, sill: 1, height: 1, kind: 'window' },
      ],
      { sky: { type: 'uniform', sun: { latitude: 47.5, longitude: 8.5, timeZone: '-05:30', date: '2030-12-21', time: '15:45:30' } } },
    );
    const parsed3 = parseLightingScene(three, 's');
    const written3 = JSON.parse(JSON.stringify(lightingSceneJson(parsed3)));
    expect(written3.room.openings).toEqual(three.room.openings);
    expect(written3.sky.sun).toEqual({ latitude: 47.5, longitude: 8.5, timeZone: '-05:30', date: '2030-12-21', time: '15:45:30' });
    expect(parseLightingScene(written3, 'again.json')).toEqual(parsed3);
  });

  it.each([
    [v2({ windows: [{ wall: 'ceiling', u: 1, v: 1, width: 1, height: 1 }] }), 'scene.json: windows[0].wall: a window in the ceiling (a skylight) is not baked yet; put it in a wall'],
    [v2({ windows: [{ wall: 'floor', u: 1, v: 1, width: 1, height: 1 }] }), 'scene.json: windows[0].wall: a window in the floor sees no sky (ceiling, north, south, west or east)'],
    [v2({ sky: { type: 'cie-clear' } }), "scene.json: sky.sun: is missing: a clear sky needs the sun's place, date and time"],
    [v3([{ wall: 0, offset: 1, width: 1, sill: 0, height: 2, kind: 'door', transmittance: 0.5 }]), 'scene.json: room.openings[0].transmittance: only a window has glazing (this opening is a door)'],
    [v3([], { windows: [] }), 'scene.json: windows: a version-3 room has its windows in room.openings (kind "window", with "transmittance")'],
    [v3([{ wall: 0, offset: 1, width: 1, sill: 1, height: 1, kind: 'window', transmitance: 0.5 }]), "scene.json: room.openings[0].transmitance: unknown field 'transmitance' (did you mean 'transmittance'?)"],
  ])('refuses %j', (json, message) => {
    expect(refusal(json)).toBe(message);
  });
});
