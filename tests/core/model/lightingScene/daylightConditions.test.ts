import { describe, expect, it } from 'vitest';
import { daylightAvailability } from '../../../../src/core/daylight/daylightAvailability';
import { solarPosition } from '../../../../src/core/daylight/solarPosition';
import { boxWindowsAsOpenings, daylightConditions } from '../../../../src/core/model/lightingScene/daylightConditions';
import { parseSky, parseWindows } from '../../../../src/core/model/lightingScene/parseDaylight';
import { boxRoomInput } from '../../../../src/core/room/boxRoom';
import { normaliseRoom } from '../../../../src/core/room/normaliseRoom';
import { roomSurfaces } from '../../../../src/core/room/roomSurfaces';

const SUN = { latitude: 47.4, longitude: 8.5, timeZone: '+02:00', date: '2026-06-21', time: '12:00' };

describe('daylight conditions from the contract', () => {
  it('a clear sky in Zurich at noon in June: the sun where NOAA puts it, sky and sun from the IES model', () => {
    const c = daylightConditions(parseSky({ type: 'cie-clear', sun: SUN }, 's'));
    const p = solarPosition({ latitude: 47.4, longitude: 8.5, timeZone: 2 }, { year: 2026, month: 6, day: 21, hours: 12 });
    expect(c.position).toEqual(p);
    const model = daylightAvailability(p.elevation, p.dayOfYear, 'clear');
    expect(c.sun?.normalIlluminance).toBeCloseTo(model.sunNormal, 9);
    expect(c.sunHorizontalIlluminance).toBeCloseTo(model.sunHorizontal, 6);
    expect(c.skyHorizontalIlluminance).toBeCloseTo(model.skyHorizontal, 9);
    expect(c.sky).toMatchObject({ kind: 'cie-general', cieType: 12, horizontalIlluminance: model.skyHorizontal });
    // The sun stands south-south-east, high: +z is south in the room.
    expect(c.sun!.direction[2]).toBeGreaterThan(0.3);
    expect(c.sun!.direction[1]).toBeCloseTo(Math.sin((p.elevation * Math.PI) / 180), 12);
  });

  it('an overcast sky reports the sun but sends none; given illuminances win; without a sun 10 klx', () => {
    const o = daylightConditions(parseSky({ type: 'cie-overcast', horizontalIlluminance: 12000, sun: SUN }, 's'));
    expect(o.sun).toBeNull();
    expect(o.position?.elevation).toBeGreaterThan(60);
    expect(o.sky.zenithLuminance).toBeCloseTo((9 * 12000) / (7 * Math.PI), 9);
    const modelled = daylightConditions(parseSky({ type: 'cie-overcast', sun: SUN }, 's'));
    expect(modelled.skyHorizontalIlluminance).toBeCloseTo(300 + 21000 * Math.sin((modelled.position!.elevation * Math.PI) / 180), 6);
    expect(daylightConditions(parseSky({ type: 'uniform' }, 's'))).toMatchObject({ sun: null, position: null, skyHorizontalIlluminance: 10000, groundReflectance: 0.2 });
    const given = daylightConditions(parseSky({ type: 'uniform', sun: { ...SUN, horizontalIlluminance: 50000 } }, 's'));
    expect(given.sunHorizontalIlluminance).toBeCloseTo(50000, 9);
    const night = daylightConditions(parseSky({ type: 'cie-overcast', sun: { ...SUN, time: '23:00' } }, 's'));
    expect(night).toMatchObject({ sun: null, skyHorizontalIlluminance: 10000 });
  });

  it('puts version-2 box windows where the wall map says, as version-3 openings', () => {
    const box = { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, east: 0.5, south: 0.5, west: 0.5 } };
    const windows = parseWindows(
      [
        { wall: 'north', u: 0.5, v: 1, width: 1, height: 1.2 },
        { wall: 'east', u: 0.4, v: 0.8, width: 1.5, height: 1 },
        { wall: 'south', u: 1, v: 0.9, width: 1.5, height: 1.4 },
        { wall: 'west', u: 2, v: 0.5, width: 1.2, height: 1.6 },
        { wall: 'ceiling', u: 2, v: 1, width: 1, height: 1 },
      ],
      box,
      's',
    );
    const { openings, skylights } = boxWindowsAsOpenings(windows, box);
    expect(skylights).toEqual([4]);
    const surfaces = roomSurfaces(normaliseRoom({ ...boxRoomInput(box), openings }));
    const holes = surfaces.flatMap((s) => s.openings.map((o) => ({ o, id: s.id })));
    // Each window's world rectangle: u along x (north/south) or z (west/east), v = y.
    const expected = [
      { id: 'wall-0', x: [0.5, 1.5], y: [1, 2.2], z: [0, 0] },
      { id: 'wall-1', x: [5, 5], y: [0.8, 1.8], z: [0.4, 1.9] },
      { id: 'wall-2', x: [1, 2.5], y: [0.9, 2.3], z: [4, 4] },
      { id: 'wall-3', x: [0, 0], y: [0.5, 2.1], z: [2, 3.2] },
    ];
    expected.forEach((e, i) => {
      const h = holes.find((x) => x.o.inputIndex === i)!;
      expect(h.id).toBe(e.id);
      const range = (a: number) => [Math.min(...h.o.polygon.map((p) => p[a])), Math.max(...h.o.polygon.map((p) => p[a]))];
      [e.x, e.y, e.z].forEach((r, a) => r.forEach((v, k) => expect(range(a)[k]).toBeCloseTo(v, 12)));
    });
  });
});
