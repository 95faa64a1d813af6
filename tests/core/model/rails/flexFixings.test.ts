/**
 * Issue 11, part 3: the flexible-angle connector (setJointTurn) and moved fixing points
 * (moveFixingPoint). Expected numbers are computed by hand from the demo catalog: flexible
 * connector arm 0.06 m (span 0.12 m at any turn, its point at the hinge), 0…±90° in 5° steps;
 * suspension every 2.0 m at most and at most 0.5 m overhang; surface clips every 1.0 m, 0.25 m.
 */
import { describe, expect, it } from 'vitest';
import data from '../../../../src/core/catalog/default-catalog.json';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { billOfMaterials } from '../../../../src/core/model/power/billOfMaterials';
import { parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { chainCoordinates } from '../../../../src/core/model/rails/chainCoordinates';
import { createConfiguration, type Configuration } from '../../../../src/core/model/configuration/configuration';
import { fixingProblem } from '../../../../src/core/model/rails/fixingRules';
import { railPlacements } from '../../../../src/core/model/rails/geometry';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { suspensionCoordinates, suspensionPoints } from '../../../../src/core/model/rails/suspensionPoints';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, run } from '../helpers';

/** Two 1 m rails through the flexible connector at `turn`, anchored at (1, z) heading +x, in an 8 × 6 × 3 m room. */
function flexChain(turn: number, z = 2, connector = 'flex'): Configuration {
  return {
    ...createConfiguration({ width: 8, depth: 6, height: 3 }),
    systems: [
      {
        id: 's1',
        x: 1,
        z,
        rotation: 0,
        suspension: catalog.suspension.default,
        rails: [
          { id: 'r2', length: 1, distribution: 'inside-centred', modules: [] },
          { id: 'r3', length: 1, distribution: 'inside-centred', modules: [] },
        ],
        joints: [{ connector, turn }],
        feeds: [{ id: 'f4', at: 'start', driver: catalog.feed.defaultDriver }],
        mounting: 'suspended',
      },
    ],
    nextId: 5,
  };
}

const points = (c: Configuration) => suspensionCoordinates(c.systems[0], catalog).map((p) => Math.round(p.s * 1e6) / 1e6);

describe('flexible-angle connector', () => {
  it('a 45° joint: the next rail starts one arm past the hinge along 45° (hand-computed)', () => {
    const c = flexChain(45);
    expect(validate(c, catalog)).toEqual([]);
    const [a, b] = railPlacements(c.systems[0], catalog);
    expect(a.end[0]).toBeCloseTo(2, 12);
    // hinge (2.06, 2); heading 45° points along (cos 45°, −sin 45°); start = hinge + 0.06·dir, end = start + 1·dir
    const r = Math.SQRT1_2;
    expect(b.start[0]).toBeCloseTo(2.06 + 0.06 * r, 12); // 2.102426
    expect(b.start[1]).toBeCloseTo(2 - 0.06 * r, 12); // 1.957574
    expect(b.end[0]).toBeCloseTo(2.06 + 1.06 * r, 12); // 2.809533
    expect(b.end[1]).toBeCloseTo(2 - 1.06 * r, 12); // 1.250467
    expect(b.heading).toBe(45);
    // The span is two arms at any turn, 0° included: hinge at s = 1.06, chain 2.12 m.
    for (const t of [0, 45, -90]) {
      const chain = chainCoordinates(flexChain(t).systems[0], catalog);
      expect(chain.jointAt[0]).toBeCloseTo(1.06, 12);
      expect(chain.length).toBeCloseTo(2.12, 12);
    }
    // The hinge's suspension sits at the hinge point.
    expect(suspensionPoints(c.systems[0], catalog)[1].plan).toEqual([2.06, 2]);
  });

  it('setJointTurn snaps to 5°, refuses past ±90°, fixed connectors and walls with the reason', () => {
    const c = flexChain(45);
    expect(run(c, 'setJointTurn', { systemId: 's1', joint: 0, degrees: 23 }).systems[0].joints[0].turn).toBe(25);
    expect(run(c, 'setJointTurn', { systemId: 's1', joint: 0, degrees: -88 }).systems[0].joints[0].turn).toBe(-90);
    expect(enabled(c, 'setJointTurn', { systemId: 's1', joint: 0, degrees: 93 })).toEqual({ ok: false, reason: 'the Flexible-angle connector turns at most ±90°' });
    expect(enabled(flexChain(90, 2, 'corner90'), 'setJointTurn', { systemId: 's1', joint: 0, degrees: 45 })).toEqual({ ok: false, reason: 'the 90° corner connector has a fixed angle; only a flexible connector can be turned' });
    expect(enabled(c, 'setJointTurn', { systemId: 's1', joint: 1, degrees: 45 })).toEqual({ ok: false, reason: 'system s1 has no connector 2' });
    // Anchored 1 m from the north wall: at 90° the second rail runs from z = 0.94 to −0.06.
    const nearWall = flexChain(45, 1);
    expect(validate(nearWall, catalog)).toEqual([]);
    expect(enabled(nearWall, 'setJointTurn', { systemId: 's1', joint: 0, degrees: 90 })).toEqual({ ok: false, reason: 'at 90° the chain would reach outside the room' });
    // Performed anyway, validate() refuses both.
    expect(validate(bindAction('setJointTurn', { systemId: 's1', joint: 0, degrees: 93 }, catalog).perform(c), catalog)[0].code).toBe('bad-turn');
    expect(validate({ ...c, systems: [{ ...c.systems[0], joints: [{ connector: 'flex', turn: 42 }] }] }, catalog)[0]).toMatchObject({ code: 'bad-turn', path: 'systems[0].joints[0].turn' });
  });

  it('extending a chain can pick it at any allowed turn; the bill lists it', () => {
    const one = { ...flexChain(0), systems: [{ ...flexChain(0).systems[0], rails: [flexChain(0).systems[0].rails[0]], joints: [] }] };
    const c = run(one, 'addRail', { systemId: 's1', connector: 'flex', turn: -30, length: 1 });
    expect(c.systems[0].joints).toEqual([{ connector: 'flex', turn: -30 }]);
    expect(enabled(one, 'addRail', { systemId: 's1', connector: 'flex', turn: 32, length: 1 })).toEqual({ ok: false, reason: 'the Flexible-angle connector turns by a multiple of 5° within ±90°' });
    const line = billOfMaterials(c, catalog).lines.find((l) => l.article === 'LX-CON-FLEX');
    expect(line).toMatchObject({ count: 1, unitPrice: 38, total: 38 });
  });

  it('the catalog states the range: maxAngle on the step grid, the default turn within it', () => {
    const bad = structuredClone(data) as { connectors: { flex?: { maxAngle: number; step: number } }[] };
    bad.connectors[2].flex = { maxAngle: 92, step: 5 };
    expect(() => parseCatalog(bad)).toThrow('connectors[2].flex.maxAngle: must be a multiple of step 5');
  });
});

describe('moving fixing points', () => {
  // Derived on the 45° chain: rail 0 inset min(0.5, 1/4) = 0.25, the hinge at 1.06, rail 1's end point 1.12 + 1 − 0.25 = 1.87.
  const c = flexChain(45);

  it('moves a point within the rules and stores every point', () => {
    expect(points(c)).toEqual([0.25, 1.06, 1.87]);
    const moved = run(c, 'moveFixingPoint', { systemId: 's1', index: 0, s: 0.403 });
    // Snapped to the centimetre; the others keep their derived values exactly.
    expect(moved.systems[0].fixings).toEqual([
      0.4,
      ...suspensionCoordinates(c.systems[0], catalog)
        .slice(1)
        .map((p) => p.s),
    ]);
    expect(points(moved)).toEqual([0.4, 1.06, 1.87]);
    expect(suspensionPoints(moved.systems[0], catalog)[0].plan[0]).toBeCloseTo(1.4, 12);
    expect(billOfMaterials(moved, catalog).lines.find((l) => l.kind === 'suspension')?.count).toBe(3);
  });

  it('refuses a move that breaks a rule, with the reason', () => {
    expect(enabled(c, 'moveFixingPoint', { systemId: 's1', index: 0, s: 0.6 })).toEqual({ ok: false, reason: 'cannot move the point to 0.6 m: the chain start would overhang its first suspension by 0.6 m (at most 0.5 m)' });
    expect(enabled(c, 'moveFixingPoint', { systemId: 's1', index: 1, s: 1.2 })).toEqual({ ok: false, reason: 'this point holds connector 1; a connector is always a support' });
    expect(enabled(c, 'moveFixingPoint', { systemId: 's1', index: 2, s: 1.0 })).toEqual({ ok: false, reason: 'cannot move the point to 1 m: suspension point 3 must lie past point 2 along the chain' });
    expect(enabled(c, 'moveFixingPoint', { systemId: 's1', index: 3, s: 1.0 })).toEqual({ ok: false, reason: 'system s1 has 3 fixing points, not 4' });
    // A 3 m rail: points at 0.5 and 2.5; the first at 0.3 leaves a 2.2 m gap (at most 2.0).
    const long = { ...c, systems: [{ ...c.systems[0], rails: [{ ...c.systems[0].rails[0], length: 3 }], joints: [] }] };
    expect(points(long)).toEqual([0.5, 2.5]);
    expect(enabled(long, 'moveFixingPoint', { systemId: 's1', index: 0, s: 0.3 })).toEqual({ ok: false, reason: 'cannot move the point to 0.3 m: suspension points 1 and 2 would be 2.2 m apart (at most 2 m)' });
    // Inside the connector's bridge (1.0 … 1.12), not on a rail and not at the hinge.
    expect(fixingProblem(c.systems[0], [0.25, 1.06, 1.1, 1.87], catalog)).toMatchObject({ code: 'fixing-off-rail', index: 2 });
    // validate() judges a stored list on its own: one without the hinge's point.
    expect(validate({ ...c, systems: [{ ...c.systems[0], fixings: [0.25, 1.5, 1.87] }] }, catalog)[0]).toMatchObject({ code: 'fixing-joint', path: 'systems[0].fixings[1]' });
  });

  it('chain changes keep moved points that still hold, else reset them in the same action', () => {
    const moved = run(c, 'moveFixingPoint', { systemId: 's1', index: 2, s: 1.8 });
    // Rail 1 at 1.1 m: chain 2.22 m, tail 0.42 ≤ 0.5: kept.
    expect(run(moved, 'setRailLength', { railId: 'r3', length: 1.1 }).systems[0].fixings).toEqual(moved.systems[0].fixings);
    // Rail 1 at 2 m: tail 1.32 > 0.5: derived again, rail 1's end point 1.12 + 2 − 0.5 = 2.62.
    const longer = run(moved, 'setRailLength', { railId: 'r3', length: 2 });
    expect(longer.systems[0].fixings).toBeUndefined();
    expect(points(longer)).toEqual([0.25, 1.06, 2.62]);
    // Clips: overhang at most 0.25, the tail 0.32 breaks it: derived clips 0.25, 1.06, 1.87.
    const surface = run(moved, 'setMounting', { systemId: 's1', mounting: 'surface' });
    expect(surface.systems[0].fixings).toBeUndefined();
    expect(points(surface)).toEqual([0.25, 1.06, 1.87]);
    // Turning the hinge keeps them (the span does not depend on the turn).
    expect(run(moved, 'setJointTurn', { systemId: 's1', joint: 0, degrees: 30 }).systems[0].fixings).toEqual(moved.systems[0].fixings);
    expect(run(moved, 'removeRail', { railId: 'r3' }).systems[0].fixings).toBeUndefined();
  });

  it('scene file version 6 keeps moved points and turns; version 5 files migrate, with fixings refused', () => {
    const moved = run(run(c, 'moveFixingPoint', { systemId: 's1', index: 0, s: 0.4 }), 'setJointTurn', { systemId: 's1', joint: 0, degrees: -35 });
    const text = serializeConfiguration(moved, catalog);
    expect(JSON.parse(text).version).toBe(SCENE_FILE_VERSION);
    expect(deserializeConfiguration(text, catalog)).toEqual(moved);
    for (const version of [1, 2, 3, 4, 5]) {
      const old = JSON.parse(serializeConfiguration(flexChain(45), catalog));
      old.version = version;
      if (version < 4) {
        for (const s of old.configuration.systems) {
          delete s.feeds;
          delete s.mounting;
        }
      }
      if (version < 3) delete old.configuration.objects;
      expect(deserializeConfiguration(JSON.stringify(old), catalog).systems[0].joints).toEqual([{ connector: 'flex', turn: 45 }]);
    }
    const v5 = JSON.parse(text);
    v5.version = 5;
    expect(() => deserializeConfiguration(JSON.stringify(v5), catalog)).toThrow('scene file: configuration.systems[0].fixings: needs "version": 6 (this file says version 5)');
  });
});
