/**
 * Free module positions (docs/model.md, "Free positions"): moveModule's snapping (grid, rail ends,
 * neighbours), its refusals (ends, connectors, overlaps), what setDistribution, addModule and
 * setRailLength do on a freely arranged rail, validate()'s rules for hand-made states, and scene
 * file version 5. Positions are computed by hand in the comments; tolerance 1e-9 m.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import type { Catalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { freeGaps, placeInLargestGap, snapOffset } from '../../../../src/core/model/rails/freePositions';
import { modulePlacements } from '../../../../src/core/model/rails/geometry';
import { newModule } from '../../../../src/core/model/actions/presets';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, run, systemAtOneOne } from '../helpers';

/** The default catalog with a 0.1 m placement grid, so the neighbours' ends (0.15 m spots) fall between grid points. */
const coarse: Catalog = { ...catalog, rail: { ...catalog.rail, placementStep: 0.1 } };

/** One system at (1, 1) heading +x: rail r2 of 1.5 m ('start': spot m3 at 0–0.15, linear m4 at 0.15–0.75), then r5 (1 m, empty) through a straight connector. */
function twoRails(): Configuration {
  return systemAtOneOne(
    [
      { id: 'r2', length: 1.5, distribution: 'start', modules: [newModule(catalog, 'm3', 'spot'), newModule(catalog, 'm4', 'linear')] },
      { id: 'r5', length: 1, distribution: 'start', modules: [] },
    ],
    [{ connector: 'straight', turn: 0 }],
    'f6',
    7,
    { width: 8, depth: 6, height: 3 },
  );
}

const rail0 = (c: Configuration) => c.systems[0].rails[0];
const offsets = (c: Configuration, cat: Catalog = catalog) =>
  Object.fromEntries(
    modulePlacements(c.systems[0], cat)
      .filter((p) => p.railId === 'r2')
      .map((p) => [p.moduleId, p.offset]),
  );
const refusal = (c: Configuration, name: string, params: unknown, cat: Catalog = catalog): string => {
  const e = enabled(c, name, params, cat);
  if (e === true) throw new Error(`${name} was enabled`);
  return e.reason;
};
/** A refused action performed anyway gives a state validate() rejects (or throws). */
const forcedIsInvalid = (c: Configuration, name: string, params: unknown, cat: Catalog = catalog) => validate(bindAction(name, params, cat).perform(c), cat);

describe('snapOffset', () => {
  it('goes to the nearest of grid, rail ends and neighbours, ties to the grid', () => {
    // 0.15 m module on a 1.5 m rail, a neighbour at [0.8, 1.4), grid 0.1.
    const others = [[0.8, 1.4]] as const;
    expect(snapOffset(0.62, 0.15, 1.5, others, 0.1)).toBeCloseTo(0.6, 9); // grid 0.6 (0.02) beats touching 0.65 (0.03)
    expect(snapOffset(0.64, 0.15, 1.5, others, 0.1)).toBeCloseTo(0.65, 9); // touching 0.65 (0.01) beats grid 0.6 (0.04)
    expect(snapOffset(1.36, 0.15, 1.5, others, 0.1)).toBeCloseTo(1.35, 9); // rail end − length 1.35 (0.01) beats grid 1.4 (0.04)
    expect(snapOffset(1.42, 0.15, 1.5, others, 0.1)).toBeCloseTo(1.4, 9); // neighbour end 1.4 = grid 1.4
    expect(snapOffset(-0.04, 0.15, 1.5, others, 0.1)).toBe(0);
    expect(snapOffset(7.33, 0.15, 1.5, others, 0.1)).toBeCloseTo(7.3, 9); // far past the end: snapped, not clamped
  });
  it('gaps and the largest-gap placement', () => {
    expect(freeGaps(1.5, [[0.6, 1.2]])).toEqual([
      [0, 0.6],
      [1.2, 1.5],
    ]);
    // Centred in [0, 0.6]: 0.225, on the 0.1 grid 0.2 (inside the gap).
    expect(placeInLargestGap(0.15, 1.5, [[0.6, 1.2]], 0.1)).toEqual({ offset: 0.2, gap: 0.6 });
    // Gap [0, 0.65] on the 0.05 grid: centred start (0.65 − 0.15) / 2 = 0.25, on the grid.
    expect(placeInLargestGap(0.15, 1.5, [[0.65, 1.2]], 0.05)).toEqual({ offset: 0.25, gap: 0.65 });
    // Nothing long enough: the largest gap's start, for validate() to refuse.
    expect(
      placeInLargestGap(
        0.6,
        1.5,
        [
          [0, 0.2],
          [0.35, 1.2],
        ],
        0.1,
      ),
    ).toEqual({ offset: 1.2, gap: 0.3 });
  });
});

describe('moveModule', () => {
  it('makes the rail free, keeping the other modules where the distribution had them', () => {
    // linear asked at 0.83: grid 0.8 (0.03) beats rail end 1.5 − 0.6 = 0.9 (0.07) and spot end 0.15.
    const c = run(twoRails(), 'moveModule', { moduleId: 'm4', offset: 0.83 }, coarse);
    expect(rail0(c).modules.map((m) => m.offset)).toEqual([0, 0.8]);
    expect(offsets(c, coarse).m4).toBeCloseTo(0.8, 9);
    expect(validate(c, coarse)).toEqual([]);
    // plan centre of the linear: anchor x 1 + 0.8 + 0.3
    const p = modulePlacements(c.systems[0], coarse).find((q) => q.moduleId === 'm4')!;
    expect(p.centre[0]).toBeCloseTo(2.1, 9);
    expect(p.centre[1]).toBeCloseTo(1, 9);
  });
  it('snaps to a neighbour, refuses overlaps, the rail end and the connector, and reorders when a module passes a gap', () => {
    const c = run(twoRails(), 'moveModule', { moduleId: 'm4', offset: 0.83 }, coarse); // linear at [0.8, 1.4)
    expect(rail0(run(c, 'moveModule', { moduleId: 'm3', offset: 0.64 }, coarse)).modules[0].offset).toBeCloseTo(0.65, 9);
    expect(refusal(c, 'moveModule', { moduleId: 'm3', offset: 0.7 }, coarse)).toBe('Spot at 0.7–0.85 m would overlap Linear diffuser m4');
    // 1.36 → rail end 1.35, over the linear's [0.8, 1.4)
    expect(refusal(c, 'moveModule', { moduleId: 'm3', offset: 1.36 }, coarse)).toMatch(/would overlap/);
    // 1.42 → 1.4 (linear's end): [1.4, 1.55) passes the 1.5 m rail's end, where the connector sits
    expect(refusal(c, 'moveModule', { moduleId: 'm3', offset: 1.42 }, coarse)).toBe('Spot would reach 1.55 m, past the connector at the end of this 1.5 m rail');
    expect(refusal(c, 'moveModule', { moduleId: 'm3', offset: -0.3 }, coarse)).toBe('Spot would start 0.3 m before the start of this rail');
    for (const offset of [0.7, 1.36, 1.42, -0.3, 40]) expect(forcedIsInvalid(c, 'moveModule', { moduleId: 'm3', offset }, coarse).map((p) => p.code)).toEqual([expect.stringMatching(/module-overlap|module-past-end/)]);
    // Linear back to 0.3 (grid), then the spot past it to 1.3: [1.3, 1.45); the list follows rail order.
    const d = run(run(c, 'moveModule', { moduleId: 'm4', offset: 0.3 }, coarse), 'moveModule', { moduleId: 'm3', offset: 1.3 }, coarse);
    expect(rail0(d).modules.map((m) => [m.id, m.offset])).toEqual([
      ['m4', 0.3],
      ['m3', 1.3],
    ]);
  });
  it('on the second rail, the start is a connector', () => {
    const c = run(twoRails(), 'addModule', { railId: 'r5', type: 'spot' });
    expect(refusal(c, 'moveModule', { moduleId: 'm7', offset: -0.2 })).toBe('Spot would start 0.2 m before the connector at the start of this rail');
  });
});

describe('a freely arranged rail', () => {
  const free = () => run(run(twoRails(), 'moveModule', { moduleId: 'm4', offset: 0.6 }, coarse), 'removeModule', { moduleId: 'm3' }, coarse); // linear alone at [0.6, 1.2)
  it('setDistribution clears the free positions in one step', () => {
    const c = run(free(), 'setDistribution', { railId: 'r2', distribution: 'end' }, coarse);
    expect(rail0(c).modules.every((m) => m.offset === undefined)).toBe(true);
    expect(offsets(c, coarse).m4).toBeCloseTo(0.9, 9); // packed against the 1.5 m end
  });
  it('addModule goes centred and snapped into the largest gap, or is refused naming it', () => {
    const c = run(free(), 'addModule', { railId: 'r2', type: 'spot', index: 1 }, coarse); // index ignored on a free rail
    expect(rail0(c).modules.map((m) => [m.id, m.offset])).toEqual([
      ['m7', 0.2],
      ['m4', 0.6],
    ]);
    // gaps now [0, 0.2], [0.35, 0.6], [1.2, 1.5]: largest 0.3 m, a 0.6 m linear does not fit
    expect(refusal(c, 'addModule', { railId: 'r2', type: 'linear' }, coarse)).toBe('no free gap on this rail holds a Linear diffuser (0.6 m): the largest is 0.3 m; move modules apart or choose a distribution');
    expect(forcedIsInvalid(c, 'addModule', { railId: 'r2', type: 'linear' }, coarse).map((p) => p.code)).toEqual(['module-past-end']); // at 1.2, the largest gap's start
  });
  it('setRailLength refuses to cut a free module off and names the shortest length', () => {
    expect(refusal(free(), 'setRailLength', { railId: 'r2', length: 1.1 }, coarse)).toBe('1.1 m would cut off modules; this rail needs at least 1.2 m (remove modules to shorten it)');
    expect(rail0(run(free(), 'setRailLength', { railId: 'r2', length: 1.2 }, coarse)).length).toBe(1.2);
  });
  it('setModuleType refuses a type that would overlap or pass the end', () => {
    expect(refusal(free(), 'setModuleType', { moduleId: 'm4', type: 'updown' }, coarse)).toMatch(/does not fit here/); // 1.25 m from 0.6 passes 1.5
  });
});

describe('validate() of free positions', () => {
  const withMods = (mods: { id: string; type: string; offset?: number }[]): Configuration => {
    const c = twoRails();
    const s = c.systems[0];
    return { ...c, systems: [{ ...s, rails: [{ ...s.rails[0], modules: mods.map((m) => ({ ...newModule(catalog, m.id, m.type), ...(m.offset === undefined ? {} : { offset: m.offset }) })) }, s.rails[1]] }] };
  };
  it('names mixed, past-end, overlapping and out-of-order modules', () => {
    const problem = (mods: { id: string; type: string; offset?: number }[]) => validate(withMods(mods), catalog).map((p) => [p.code, p.path]);
    expect(
      problem([
        { id: 'm3', type: 'spot', offset: 0 },
        { id: 'm4', type: 'linear', offset: 0.15 },
      ]),
    ).toEqual([]);
    expect(
      problem([
        { id: 'm3', type: 'spot', offset: 0 },
        { id: 'm4', type: 'linear' },
      ]),
    ).toEqual([['module-position', 'systems[0].rails[0].modules[1].offset']]);
    expect(problem([{ id: 'm3', type: 'spot', offset: -0.01 }])).toEqual([['module-past-end', 'systems[0].rails[0].modules[0].offset']]);
    expect(problem([{ id: 'm4', type: 'linear', offset: 0.95 }])).toEqual([['module-past-end', 'systems[0].rails[0].modules[0].offset']]); // 0.95 + 0.6 > 1.5
    expect(problem([{ id: 'm4', type: 'linear', offset: 0.9 }])).toEqual([]); // touches the end exactly
    expect(
      problem([
        { id: 'm3', type: 'spot', offset: 0 },
        { id: 'm4', type: 'linear', offset: 0.1 },
      ]),
    ).toEqual([['module-overlap', 'systems[0].rails[0].modules[1].offset']]);
    expect(
      problem([
        { id: 'm4', type: 'linear', offset: 0.5 },
        { id: 'm3', type: 'spot', offset: 0 },
      ]),
    ).toEqual([['module-overlap', 'systems[0].rails[0].modules[1].offset']]);
  });
});

describe('scene file version 5', () => {
  it('saves and reads free positions', () => {
    const c = run(twoRails(), 'moveModule', { moduleId: 'm4', offset: 0.83 });
    const file = JSON.parse(serializeConfiguration(c, catalog));
    expect(file.version).toBe(SCENE_FILE_VERSION);
    expect(file.configuration.systems[0].rails[0].modules[1].offset).toBe(0.85);
    expect(deserializeConfiguration(serializeConfiguration(c, catalog), catalog)).toEqual(c);
  });
  it('migrates versions 1 to 4 (no free positions) and refuses an offset in any of them', () => {
    const v1 = JSON.parse(readFileSync('tests/fixtures/configurations/corner-l.luxbox.json', 'utf8'));
    expect(v1.version).toBe(1);
    const fromV1 = deserializeConfiguration(JSON.stringify(v1), catalog);
    for (const version of [2, 3]) expect(deserializeConfiguration(JSON.stringify({ ...v1, version }), catalog)).toEqual(fromV1);
    const v4 = { ...JSON.parse(serializeConfiguration(fromV1, catalog)), version: 4 };
    expect(deserializeConfiguration(JSON.stringify(v4), catalog)).toEqual(fromV1);
    expect(fromV1.systems.flatMap((s) => s.rails.flatMap((r) => r.modules)).every((m) => m.offset === undefined)).toBe(true);
    for (const [version, doc] of [
      [1, v1],
      [2, v1],
      [3, v1],
      [4, v4],
    ] as const) {
      const withOffset = structuredClone(doc);
      withOffset.version = version;
      withOffset.configuration.systems[0].rails[0].modules[0].offset = 0;
      expect(() => deserializeConfiguration(JSON.stringify(withOffset), catalog)).toThrow(`configuration.systems[0].rails[0].modules[0].offset: needs "version": 5 (this file says version ${version})`);
    }
  });
});
