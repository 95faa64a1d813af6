/** setDaylight and setWindowGlazing (issue 30): what they set, what they refuse and why, undo, and a window's glazing when it stops being a window. */
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { DEFAULT_DAYLIGHT } from '../../../../src/core/model/configuration/daylightSettings';
import { createHistory, pushHistory, redo, undo } from '../../../../src/core/model/configuration/history';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, run } from '../helpers';

/** A 5 × 4 m room with two windows on its south wall (wall 2 of the rectangle) and a door. */
function livingRoom(): Configuration {
  let s = run(createConfiguration({ width: 5, depth: 4, height: 2.6 }), 'setRoomShapePreset', { preset: 'rectangle' });
  s = run(s, 'addRoomOpening', { wall: 2, kind: 'window', offset: 0.6, width: 1.4, sill: 0.8, height: 1.4 });
  s = run(s, 'addRoomOpening', { wall: 2, kind: 'window', offset: 3, width: 1.4, sill: 0.8, height: 1.4 });
  return run(s, 'addRoomOpening', { wall: 0, kind: 'door' });
}

const reason = (s: Configuration, name: string, params: unknown) => {
  const e = enabled(s, name, params);
  return e === true ? null : e.reason;
};

describe('setDaylight', () => {
  it('starts from the defaults, off, and sets only what it is given', () => {
    const s = createConfiguration();
    expect(s.daylight).toBeUndefined();
    const dated = run(s, 'setDaylight', { date: '2026-12-21' });
    expect(dated.daylight).toEqual({ ...DEFAULT_DAYLIGHT, date: '2026-12-21' });
    expect(dated.daylight!.on).toBe(false);
    const on = run(dated, 'setDaylight', { on: true, time: '17:00', sky: 'cie-overcast' });
    expect(on.daylight).toEqual({ ...DEFAULT_DAYLIGHT, on: true, date: '2026-12-21', time: '17:00', sky: 'cie-overcast' });
  });

  it('places: a city, or coordinates merged onto the city they replace (its standard zone)', () => {
    const s = run(createConfiguration(), 'setDaylight', { city: 'Rome' });
    expect(s.daylight!.place).toEqual({ city: 'Rome' });
    const moved = run(s, 'setDaylight', { latitude: 42 });
    expect(moved.daylight!.place).toEqual({ latitude: 42, longitude: 12.5, timeZone: 1 });
    expect(run(moved, 'setDaylight', { timeZone: 2 }).daylight!.place).toEqual({ latitude: 42, longitude: 12.5, timeZone: 2 });
    expect(reason(s, 'setDaylight', { city: 'Rome', latitude: 4 })).toBe('give either a city or coordinates, not both');
  });

  it('refuses impossible values with the rule’s sentence, and the state stays valid', () => {
    const s = createConfiguration();
    expect(reason(s, 'setDaylight', { date: '2027-02-29' })).toBe("'2027-02-29' is not a day between 1901 and 2099 written YYYY-MM-DD");
    expect(reason(s, 'setDaylight', { date: '2100-01-01' })).toBe("'2100-01-01' is not a day between 1901 and 2099 written YYYY-MM-DD");
    expect(reason(s, 'setDaylight', { date: '2028-02-29' })).toBeNull();
    expect(reason(s, 'setDaylight', { time: '23:60' })).toBe("'23:60' is not a clock time 00:00 to 23:59");
    expect(reason(s, 'setDaylight', { city: 'Zurch' })).toBe("'Zurch' is not a city of the list; give latitude, longitude and time zone instead");
    expect(reason(s, 'setDaylight', { longitude: 181 })).toBe('the longitude must be between -180 and 180 ° (got 181)');
    expect(reason(s, 'setDaylight', { timeZone: -13 })).toBe('the time zone must be between -12 and 14 h (got -13)');
    expect(reason(s, 'setDaylight', { groundReflectance: -0.1 })).toBe("the ground's reflectance must be at least 0 and below 1 (got -0.1)");
    // A sky or preset that does not exist is a bad parameter, refused before the action is bound.
    expect(() => reason(s, 'setDaylight', { sky: 'cloudy' })).toThrow('setDaylight: sky: ');
  });

  it('undoes and redoes through the history as every action does', () => {
    const s0 = livingRoom();
    let h = pushHistory(createHistory(s0), run(s0, 'setDaylight', { on: true }));
    h = pushHistory(h, run(h.present, 'setDaylight', { time: '17:00', date: '2026-12-21' }));
    expect(h.present.daylight).toMatchObject({ on: true, time: '17:00', date: '2026-12-21' });
    h = undo(h);
    expect(h.present.daylight).toMatchObject({ on: true, time: '10:00', date: '2026-06-21' });
    h = undo(h);
    expect(h.present).toBe(s0);
    h = redo(redo(h));
    expect(h.present.daylight).toMatchObject({ time: '17:00' });
  });
});

describe('setWindowGlazing', () => {
  it('sets a preset or a number on a window; a door or a missing opening is refused', () => {
    const s = livingRoom();
    const triple = run(s, 'setWindowGlazing', { opening: 0, transmittance: 'triple' });
    expect(triple.room.shape!.openings[0].transmittance).toBe('triple');
    expect(triple.room.shape!.openings[1].transmittance).toBeUndefined();
    expect(run(triple, 'setWindowGlazing', { opening: 1, transmittance: 0.5 }).room.shape!.openings[1].transmittance).toBe(0.5);
    expect(reason(s, 'setWindowGlazing', { opening: 2, transmittance: 'double' })).toBe('opening 2 is a door; only a window has glazing');
    expect(reason(s, 'setWindowGlazing', { opening: 7, transmittance: 'double' })).toBe('the room has no opening 7');
    expect(reason(s, 'setWindowGlazing', { opening: 0, transmittance: 1.01 })).toBe('the glazing of window 0 must be single, double, triple or a transmittance from 0 to 1 (got 1.01)');
    expect(() => reason(s, 'setWindowGlazing', { opening: 0, transmittance: 'quadruple' })).toThrow('setWindowGlazing: transmittance: ');
  });

  it('a window made a door leaves its glazing; moving or splitting the wall keeps it', () => {
    const glazed = run(livingRoom(), 'setWindowGlazing', { opening: 1, transmittance: 'single' });
    const door = run(glazed, 'setRoomOpening', { opening: 1, kind: 'door', sill: 0, height: 2 });
    expect(door.room.shape!.openings[1]).not.toHaveProperty('transmittance');
    expect(validate(door, catalog)).toEqual([]);
    const moved = run(glazed, 'setRoomOpening', { opening: 1, offset: 3.2 });
    expect(moved.room.shape!.openings[1].transmittance).toBe('single');
    const split = run(glazed, 'splitRoomWall', { wall: 2, at: 2.5 });
    expect(split.room.shape!.openings.filter((o) => o.transmittance === 'single')).toHaveLength(1);
  });

  it('a refused action would really break validate() (the always-valid contract)', () => {
    const s = livingRoom();
    const broken = bindAction('setWindowGlazing', { opening: 0, transmittance: 2 }, catalog).perform(s);
    expect(validate(broken, catalog).map((p) => p.code)).toEqual(['window-glazing']);
    const night = bindAction('setDaylight', { time: '25:00' }, catalog).perform(s);
    expect(validate(night, catalog).map((p) => p.path)).toEqual(['daylight.time']);
  });
});
