import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { modulePlacements, systemBounds } from '../../../../src/core/model/rails/geometry';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, only, powered, run, withPreset } from '../helpers';

/** A refused action, performed anyway, must yield a state validate() rejects (or throw). */
function expectRefusedAndInvalid(state: Configuration, name: string, params: unknown, reason: RegExp) {
  const a = bindAction(name, params, catalog);
  const e = a.isEnabled(state);
  expect(e).toEqual({ ok: false, reason: expect.stringMatching(reason) });
  let next: Configuration;
  try {
    next = a.perform(state);
  } catch {
    return;
  }
  expect(validate(next, catalog).length).toBeGreaterThan(0);
}

describe('plus button: add modules until the rail is full', () => {
  it('takes ten 0.15 m spots on a 1.5 m rail, then disables', () => {
    // Fed from both ends by 321.6 W drivers: ten 43 W spots (430 W) fit electrically, so the rail's length decides.
    let s = powered(withPreset('single', 1, 1));
    const rail = only(s).rails[0].id;
    let added = 0;
    while (enabled(s, 'addModule', { railId: rail, type: 'spot' }) === true) {
      s = run(s, 'addModule', { railId: rail, type: 'spot' });
      added++;
    }
    expect(added).toBe(7); // preset has 3; 10 × 0.15 = 1.5
    expect(validate(s, catalog)).toEqual([]);
    expectRefusedAndInvalid(s, 'addModule', { railId: rail, type: 'spot' }, /no room for another Spot/);
  });
  it('inserts at an index and re-lays out', () => {
    let s = powered(withPreset('single', 1, 1));
    const rail = only(s).rails[0];
    s = run(s, 'addModule', { railId: rail.id, type: 'flood', index: 0 });
    expect(only(s).rails[0].modules.map((m) => m.type)).toEqual(['flood', 'spot', 'spot', 'spot']);
    // inside-centred, 4 cells of 0.375 m: first module centre at 0.1875
    expect(modulePlacements(only(s), catalog)[0].offset).toBeCloseTo(0.1875 - 0.075, 12);
  });
});

describe('distribution options', () => {
  it('disables centred options that would not fit mixed lengths, keeps start/end', () => {
    let s = withPreset('single', 1, 1);
    const rail = only(s).rails[0];
    // spot, spot, spot → spot, linear(0.6), spot, spot: total 1.05 ≤ 1.5, cells 0.375 < 0.6
    s = run(s, 'setDistribution', { railId: rail.id, distribution: 'start' });
    s = run(s, 'addModule', { railId: rail.id, type: 'linear', index: 1 });
    for (const d of ['start', 'end', 'outside-centred']) expect(enabled(s, 'setDistribution', { railId: rail.id, distribution: d })).toBe(true);
    expectRefusedAndInvalid(s, 'setDistribution', { railId: rail.id, distribution: 'inside-centred' }, /do not fit 'inside-centred'/);
  });
});

describe('module type switch', () => {
  it('only to types that fit without clashing', () => {
    let s = powered(withPreset('single', 1, 1));
    const rail = only(s).rails[0];
    s = run(s, 'setDistribution', { railId: rail.id, distribution: 'start' });
    for (let i = 0; i < 6; i++) s = run(s, 'addModule', { railId: rail.id, type: 'spot' });
    // packed from the start, 9 spots = 1.35 m on 1.5 m: a 0.25 m washer fits instead of one spot (1.45), a 0.6 m linear does not
    const m = only(s).rails[0].modules[4].id;
    expect(enabled(s, 'setModuleType', { moduleId: m, type: 'washer' })).toBe(true);
    expectRefusedAndInvalid(s, 'setModuleType', { moduleId: m, type: 'linear' }, /Linear diffuser \(0\.6 m\) does not fit/);
    const w = run(s, 'setModuleType', { moduleId: m, type: 'washer' });
    expect(only(w).rails[0].modules[4]).toMatchObject({ type: 'washer', beam: 'left', cct: 3000 });
  });
  it('keeps the CCT where offered, else the new default', () => {
    let s = withPreset('single', 1, 1);
    const m = only(s).rails[0].modules[0].id;
    s = run(s, 'setModuleCct', { moduleId: m, cct: 2700 });
    expect(only(run(s, 'setModuleType', { moduleId: m, type: 'flood' })).rails[0].modules[0].cct).toBe(2700);
    const onRailOfOwn = powered(run(createConfiguration({ width: 8, depth: 6, height: 3 }), 'placePreset', { presetId: 'long-line', x: 1, z: 1 }));
    const mm = only(onRailOfOwn).rails[0].modules[1].id; // a flood between linears on a 3 m rail
    expect(only(run(onRailOfOwn, 'setModuleType', { moduleId: mm, type: 'updown' })).rails[0].modules[1].cct).toBe(3000);
  });
});

describe('module settings', () => {
  it('CCT only from the type, beam only from the type, dimming in 0..1', () => {
    const s = withPreset('single', 1, 1);
    const m = only(s).rails[0].modules[0].id;
    expect(enabled(s, 'setModuleCct', { moduleId: m, cct: 4000 })).toBe(true);
    expectRefusedAndInvalid(s, 'setModuleCct', { moduleId: m, cct: 6500 }, /2700, 3000, 4000 K only/);
    expect(only(run(s, 'setModuleBeam', { moduleId: m, beam: 'medium' })).rails[0].modules[0].beam).toBe('medium');
    expectRefusedAndInvalid(s, 'setModuleBeam', { moduleId: m, beam: 'flood48' }, /no beam 'flood48'/);
    expectRefusedAndInvalid(s, 'setModuleDimming', { moduleId: m, dimming: 1.5 }, /between 0 and 1/);
  });
});

describe('rail length', () => {
  it('snaps to the 0.1 m step and refuses lengths that cut off modules, naming the minimum', () => {
    let s = powered(withPreset('single', 1, 1));
    const rail = only(s).rails[0].id;
    s = run(s, 'setRailLength', { railId: rail, length: 2.04 });
    expect(only(s).rails[0].length).toBe(2);
    // three 0.15 m spots need 0.45 m, so the 0.5 m minimum is fine
    expect(enabled(s, 'setRailLength', { railId: rail, length: 0.5 })).toBe(true);
    for (let i = 0; i < 5; i++) s = run(s, 'addModule', { railId: rail, type: 'spot' });
    expectRefusedAndInvalid(s, 'setRailLength', { railId: rail, length: 1.1 }, /cut off modules; this rail needs at least 1.2 m/);
    expectRefusedAndInvalid(s, 'setRailLength', { railId: rail, length: 3.2 }, /between 0.5 and 3 m/);
  });
  it('refuses a length that would push the chain out of the room', () => {
    const s = withPreset('single', 6, 1); // 8 m wide room, rail from x = 6 to 7.5
    expect(enabled(s, 'setRailLength', { railId: only(s).rails[0].id, length: 2 })).toBe(true);
    expectRefusedAndInvalid(s, 'setRailLength', { railId: only(s).rails[0].id, length: 2.1 }, /outside the 8 × 6 m room/);
  });
});

describe('systems stay inside the room and below the ceiling', () => {
  it('move refused outside the walls', () => {
    const s = withPreset('single', 1, 1);
    const id = only(s).id;
    expect(enabled(s, 'moveSystem', { systemId: id, x: 6.5, z: 5.975 })).toBe(true);
    expectRefusedAndInvalid(s, 'moveSystem', { systemId: id, x: 6.51, z: 1 }, /outside/);
    expectRefusedAndInvalid(s, 'moveSystem', { systemId: id, x: 1, z: 0.01 }, /outside/);
  });
  it('rotation turns about the footprint centre and is refused where it would leave the room', () => {
    const room = { width: 2, depth: 2, height: 3 };
    let s = withPreset('single', 0.25, 1, 0, room); // 1.5 m rail centred in a 2 m room
    const id = only(s).id;
    const before = systemBounds(only(s), catalog);
    s = run(s, 'rotateSystem', { systemId: id, by: 90 });
    const after = systemBounds(only(s), catalog);
    expect((after.minX + after.maxX) / 2).toBeCloseTo((before.minX + before.maxX) / 2, 12);
    expect(after.maxZ - after.minZ).toBeCloseTo(1.5, 12);
    expect(only(s).rotation).toBe(90);
    const narrow = withPreset('single', 0.25, 0.5, 0, { width: 2, depth: 1, height: 3 });
    expectRefusedAndInvalid(narrow, 'rotateSystem', { systemId: only(narrow).id, by: 90 }, /cannot rotate here/);
  });
  it('four quarter turns come back to the start', () => {
    let s = withPreset('corner-l', 2, 4);
    const start = only(s);
    for (let i = 0; i < 4; i++) s = run(s, 'rotateSystem', { systemId: start.id, by: 90 });
    expect(only(s).x).toBeCloseTo(start.x, 9);
    expect(only(s).z).toBeCloseTo(start.z, 9);
    expect(only(s).rotation).toBe(0);
  });
  it('suspension within the catalog range and keeping head room', () => {
    const s = withPreset('single', 1, 1); // ceiling 3 m, head room 2 m → suspension ≤ 1 m
    const id = only(s).id;
    expect(enabled(s, 'setSuspension', { systemId: id, suspension: 1 })).toBe(true);
    expectRefusedAndInvalid(s, 'setSuspension', { systemId: id, suspension: 1.01 }, /below the minimum 2 m above the floor/);
    expectRefusedAndInvalid(s, 'setSuspension', { systemId: id, suspension: 0.05 }, /between 0.1 and 2 m/);
  });
  it('room changes refused when a system would not fit', () => {
    const s = withPreset('single', 5, 1);
    expect(enabled(s, 'setRoom', { width: 6.5, depth: 6, height: 3 })).toBe(true);
    expectRefusedAndInvalid(s, 'setRoom', { width: 6.4, depth: 6, height: 3 }, /a placed system would not fit/);
    expectRefusedAndInvalid(s, 'setRoom', { width: 0.5, depth: 6, height: 3 }, /room width must be between 1 and 30 m/);
    // suspension 0.6 m: a 2.5 m room leaves 1.9 m head room
    expectRefusedAndInvalid(s, 'setRoom', { width: 8, depth: 6, height: 2.5 }, /above the floor/);
  });
});

describe('presets and clashes', () => {
  it('every preset places into an empty 8 × 6 m room at a free spot and validates', () => {
    for (const p of catalog.presets) {
      const s = run(createConfiguration({ width: 8, depth: 6, height: 3 }), 'placePreset', { presetId: p.id });
      expect(validate(s, catalog)).toEqual([]);
      expect(only(s).presetId).toBe(p.id);
    }
  });
  it('finds free space next to an existing system, refuses when none is left', () => {
    let s = createConfiguration({ width: 3, depth: 2, height: 3 });
    s = run(s, 'placePreset', { presetId: 'single' });
    s = run(s, 'placePreset', { presetId: 'single' });
    expect(validate(s, catalog)).toEqual([]);
    expect(enabled(s, 'placePreset', { presetId: 'long-line' })).toEqual({ ok: false, reason: "no free space for 'Long line' in this room" });
  });
  it('moving one system onto another is refused', () => {
    let s = withPreset('single', 1, 1);
    s = run(s, 'placePreset', { presetId: 'single', x: 1, z: 2 });
    expectRefusedAndInvalid(s, 'moveSystem', { systemId: s.systems[1].id, x: 1.5, z: 1.02 }, /overlaps system/);
  });
  it('a room too low for any suspension refuses presets', () => {
    const s = createConfiguration({ width: 4, depth: 4, height: 2.05 });
    expect(enabled(s, 'placePreset', { presetId: 'single' })).toEqual({ ok: false, reason: expect.stringMatching(/too low/) });
  });
  it('a snake cannot be grown into itself', () => {
    let s = withPreset('single', 3, 3);
    const id = only(s).id;
    s = run(s, 'addRail', { systemId: id, connector: 'corner90', turn: 90, length: 0.5 });
    s = run(s, 'addRail', { systemId: id, connector: 'corner90', turn: 90, length: 1 });
    // the fourth rail would head +z from x ≈ 3.45 across the first rail (x 3..4.5 at z = 3)
    expectRefusedAndInvalid(s, 'addRail', { systemId: id, connector: 'corner90', turn: 90, length: 1 }, /runs into itself/);
    expectRefusedAndInvalid(s, 'addRail', { systemId: id, connector: 'corner90', turn: 45 }, /turns by ±90°/);
  });
  it('any rail can be removed (removeRail.test.ts), but never the only one', () => {
    const s = withPreset('u-shape', 1, 4);
    const rails = only(s).rails;
    expect(enabled(s, 'removeRail', { railId: rails[2].id })).toBe(true);
    expect(enabled(s, 'removeRail', { railId: rails[0].id })).toBe(true);
    const one = withPreset('single', 1, 1);
    expectRefusedAndInvalid(one, 'removeRail', { railId: only(one).rails[0].id }, /keeps at least one rail/);
  });
  it('delete removes the system; unknown ids are refused', () => {
    const s = withPreset('single', 1, 1);
    expect(run(s, 'deleteSystem', { systemId: only(s).id }).systems).toEqual([]);
    expectRefusedAndInvalid(s, 'deleteSystem', { systemId: 'nope' }, /no system with id 'nope'/);
  });
});
