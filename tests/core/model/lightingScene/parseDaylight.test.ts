/** The daylight contract (docs/scene-format.md "Daylight"): windows, sky, sun, version-3 glazing, and every refusal's one line. */
import { describe, expect, it } from 'vitest';
import { parseDaylight, parseOpeningGlazing, parseSky, parseWindows } from '../../../../src/core/model/lightingScene/parseDaylight';
import { LightingSceneError } from '../../../../src/core/model/lightingScene/parseLightingScene';

const ROOM = { width: 5, height: 2.8, depth: 4, reflectance: {} };
const SUN = { latitude: 47.4, longitude: 8.5, timeZone: '+02:00', date: '2026-06-21', time: '12:00' };
const win = (extra: Record<string, unknown> = {}) => ({ wall: 'south', u: 1, v: 0.9, width: 1.5, height: 1.4, ...extra });

const refusal = (f: () => unknown): string => {
  try {
    f();
  } catch (error) {
    expect(error).toBeInstanceOf(LightingSceneError);
    return (error as Error).message;
  }
  throw new Error('accepted');
};

describe('daylight contract: windows (version 2)', () => {
  it('reads the documented example, with presets, numbers and the default glazing', () => {
    const [a, b, c] = parseWindows([win({ transmittance: 0.7 }), win({ wall: 'east', u: 0.5, transmittance: 'triple' }), win({ wall: 'ceiling', u: 2, v: 1, width: 1, height: 1 })], ROOM, 'scene.json');
    expect(a).toMatchObject({ wall: 'south', u: 1, v: 0.9, width: 1.5, height: 1.4, transmittance: 0.7, glazing: { normalTransmittance: 0.7, panes: 1 } });
    expect(b.glazing).toMatchObject({ normalTransmittance: 0.6, panes: 3 });
    expect(c).toMatchObject({ transmittance: 'double', glazing: { normalTransmittance: 0.75, panes: 2 } });
    expect(parseWindows([win({ transmittance: 1 })], ROOM, 's')[0].glazing).toMatchObject({ normalTransmittance: 1, panes: 0 });
    expect(parseDaylight({ room: ROOM }, 's')).toEqual({ windows: [] });
  });

  it.each([
    [[win({ wall: 'floor' })], 'scene.json: windows[0].wall: a window in the floor sees no sky (ceiling, north, south, west or east)'],
    [[win({ wall: 'souht' })], 'scene.json: windows[0].wall: "souht" is not a wall: ceiling, north, south, west or east'],
    [[win({ hieght: 1 })], "scene.json: windows[0].hieght: unknown field 'hieght' (did you mean 'height'?)"],
    [[win({ width: 0 })], 'scene.json: windows[0].width: 0 m must be greater than 0'],
    [[win({ u: -0.5 })], 'scene.json: windows[0].u: -0.5 m is negative'],
    [[win({ transmittance: 1.2 })], 'scene.json: windows[0].transmittance: transmittance 1.2 is outside 0 … 1 (1 = an open window)'],
    [[win({ transmittance: 'quadruple' })], 'scene.json: windows[0].transmittance: must be a number in 0 … 1 or "single", "double" or "triple", got "quadruple"'],
    [[win({ u: 4 })], 'scene.json: windows[0].width: the window reaches from 4 to 5.5 m along the south wall (u = x), which ends at 5 m'],
    [[win({ wall: 'west', u: 3 })], 'scene.json: windows[0].width: the window reaches from 3 to 4.5 m along the west wall (u = z), which ends at 4 m'],
    [[win({ v: 2 })], 'scene.json: windows[0].height: the window reaches from 2 to 3.4 m up the south wall (v = y), which ends at 2.8 m'],
    [[win(), win({ u: 2 })], 'scene.json: windows[1]: overlaps windows[0] on the south wall (windows may touch, not overlap)'],
    [{ wall: 'south' }, 'scene.json: windows: must be an array'],
    [[42], 'scene.json: windows[0]: must be an object'],
  ])('refuses %j with one line naming the path', (windows, message) => {
    expect(refusal(() => parseDaylight({ windows, room: ROOM }, 'scene.json'))).toBe(message);
  });

  it('lets windows touch, and leaves an unreadable room to the room reader', () => {
    expect(parseWindows([win(), win({ u: 2.5 }), win({ wall: 'north' })], ROOM, 's')).toHaveLength(3);
    expect(parseWindows([win({ u: 400 })], { width: 'wide' }, 's')).toHaveLength(1);
    expect(
      refusal(() =>
        parseWindows(
          Array.from({ length: 101 }, () => win()),
          ROOM,
          's',
        ),
      ),
    ).toBe('s: windows: more than 100 windows');
  });
});

describe('daylight contract: sky and sun', () => {
  it('reads the documented example and fills the defaults', () => {
    const sky = parseSky({ type: 'cie-overcast', horizontalIlluminance: 10000, sun: { ...SUN, timeZone: '+01:00' } }, 's');
    expect(sky).toEqual({ type: 'cie-overcast', horizontalIlluminance: 10000, groundReflectance: 0.2, sun: { latitude: 47.4, longitude: 8.5, timeZone: 1, year: 2026, month: 6, day: 21, hours: 12 } });
    expect(parseSky({ type: 'uniform' }, 's')).toEqual({ type: 'uniform', groundReflectance: 0.2 });
    const clear = parseSky({ type: 'cie-clear', groundReflectance: 0.3, sun: { city: 'zurich', timeZone: '+02:00', date: '2026-06-21', time: '10:30:15', horizontalIlluminance: 60000 } }, 's');
    expect(clear.sun).toEqual({ latitude: 47.4, longitude: 8.5, timeZone: 2, city: 'Zurich', year: 2026, month: 6, day: 21, hours: 10.5 + 15 / 3600, horizontalIlluminance: 60000 });
    // A city alone keeps its standard time; "Z" is UTC.
    expect(parseSky({ type: 'uniform', sun: { city: 'New York', date: '2026-12-21', time: '12:00' } }, 's').sun?.timeZone).toBe(-5);
    expect(parseSky({ type: 'uniform', sun: { ...SUN, timeZone: 'Z' } }, 's').sun?.timeZone).toBe(0);
    expect(parseSky({ type: 'uniform', sun: { ...SUN, timeZone: '-03:30' } }, 's').sun?.timeZone).toBe(-3.5);
  });

  it.each([
    [{ type: 'clear' }, 'scene.json: sky.type: "clear" is not a sky type: "uniform", "cie-overcast" or "cie-clear"'],
    [{}, 'scene.json: sky.type: is missing ("uniform", "cie-overcast" or "cie-clear")'],
    [{ type: 'uniform', horizontalIlluminance: 0 }, 'scene.json: sky.horizontalIlluminance: 0 lx is outside (0, 150000] lx'],
    [{ type: 'uniform', horizontalIluminance: 5 }, "scene.json: sky.horizontalIluminance: unknown field 'horizontalIluminance' (did you mean 'horizontalIlluminance'?)"],
    [{ type: 'uniform', groundReflectance: 1 }, 'scene.json: sky.groundReflectance: ground reflectance 1 is outside [0, 1)'],
    [{ type: 'cie-clear' }, "scene.json: sky.sun: is missing: a clear sky needs the sun's place, date and time"],
    [{ type: 'cie-overcast', sun: { ...SUN, horizontalIlluminance: 50000 } }, 'scene.json: sky.sun.horizontalIlluminance: an overcast sky has no direct sun (its position is only reported)'],
    [{ type: 'uniform', sun: { ...SUN, time: '23:30', horizontalIlluminance: 50000 } }, 'scene.json: sky.sun.horizontalIlluminance: the sun is below the horizon then (elevation -14.3°)'],
    [{ type: 'cie-clear', sun: { ...SUN, date: '2026-12-21', time: '18:00' } }, 'scene.json: sky.sun.time: the sun is below the horizon then (elevation -3.9°): a clear sky needs it up'],
    [{ type: 'uniform', sun: { ...SUN, latitude: 91 } }, 'scene.json: sky.sun.latitude: 91° is outside −90 … 90° (north positive)'],
    [{ type: 'uniform', sun: { ...SUN, longitude: -200 } }, 'scene.json: sky.sun.longitude: -200° is outside −180 … 180° (east positive)'],
    [{ type: 'uniform', sun: { ...SUN, latitude: undefined } }, 'scene.json: sky.sun.latitude: is missing (or name a city)'],
    [{ type: 'uniform', sun: { date: '2026-06-21', time: '12:00', latitude: 1, longitude: 2 } }, 'scene.json: sky.sun.timeZone: is missing (or name a city)'],
    [{ type: 'uniform', sun: { ...SUN, city: 'Zurich' } }, 'scene.json: sky.sun.latitude: give either a city or latitude and longitude, not both'],
    [{ type: 'uniform', sun: { city: 'Zurch', date: '2026-06-21', time: '12:00' } }, 'scene.json: sky.sun.city: unknown city "Zurch" (did you mean \'Zurich\'?); give latitude, longitude and timeZone instead'],
    [{ type: 'uniform', sun: { ...SUN, date: '2026-02-30' } }, 'scene.json: sky.sun.date: "2026-02-30" is not a day of the calendar'],
    [{ type: 'uniform', sun: { ...SUN, date: '21.06.2026' } }, 'scene.json: sky.sun.date: "21.06.2026" is not a date "YYYY-MM-DD"'],
    [{ type: 'uniform', sun: { ...SUN, date: '1850-06-21' } }, 'scene.json: sky.sun.date: year 1850 is outside 1901 … 2099 (where the solar-position algorithm holds)'],
    [{ type: 'uniform', sun: { ...SUN, time: '24:00' } }, 'scene.json: sky.sun.time: "24:00" is not a clock time (00:00 … 23:59:59)'],
    [{ type: 'uniform', sun: { ...SUN, time: 'noon' } }, 'scene.json: sky.sun.time: "noon" is not a clock time "HH:MM" or "HH:MM:SS"'],
    [{ type: 'uniform', sun: { ...SUN, timeZone: '+1' } }, 'scene.json: sky.sun.timeZone: "+1" is not an offset like "+01:00" or "-05:00" (hours ahead of UTC)'],
    [{ type: 'uniform', sun: { ...SUN, timeZone: '+15:00' } }, 'scene.json: sky.sun.timeZone: "+15:00" is outside −12:00 … +14:00'],
    [{ type: 'uniform', sun: { ...SUN, date: undefined } }, 'scene.json: sky.sun.date: is missing (YYYY-MM-DD)'],
    [{ type: 'uniform', sun: { ...SUN, lat: 4 } }, "scene.json: sky.sun.lat: unknown field 'lat'"],
    ['overcast', 'scene.json: sky: must be an object'],
  ])('refuses %j with one line naming the path', (sky, message) => {
    expect(refusal(() => parseDaylight({ sky }, 'scene.json'))).toBe(message);
  });
});

describe('daylight contract: version-3 openings', () => {
  it('gives each window its glazing, double by default, and refuses glazing on a door', () => {
    const openings = [
      { wall: 0, offset: 1, width: 1.2, sill: 0.9, height: 1.3, kind: 'window', transmittance: 'single' },
      { wall: 1, offset: 0.5, width: 0.9, sill: 0, height: 2, kind: 'door' },
      { wall: 2, offset: 1, width: 1, sill: 1, height: 1, kind: 'window' },
      { wall: 3, offset: 1, width: 1, sill: 1, height: 1, kind: 'window', transmittance: 0.55 },
    ];
    const g = parseOpeningGlazing(openings, 's');
    expect([...g.keys()]).toEqual([0, 2, 3]);
    expect(g.get(0)).toMatchObject({ normalTransmittance: 0.85, panes: 1 });
    expect(g.get(2)).toMatchObject({ normalTransmittance: 0.75, panes: 2 });
    expect(g.get(3)).toMatchObject({ normalTransmittance: 0.55, panes: 1 });
    expect(refusal(() => parseOpeningGlazing([{ ...openings[1], transmittance: 0.8 }], 'scene.json'))).toBe('scene.json: room.openings[0].transmittance: only a window has glazing (this opening is a door)');
    expect(refusal(() => parseOpeningGlazing([openings[0], { ...openings[2], transmittance: -1 }], 'scene.json'))).toBe('scene.json: room.openings[1].transmittance: transmittance -1 is outside 0 … 1 (1 = an open window)');
    expect(parseOpeningGlazing(undefined, 's').size).toBe(0);
  });
});
