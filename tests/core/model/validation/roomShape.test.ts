/**
 * validate() in a room with a shape (issue 29; docs/model.md "Room shape"): the shape's own rules
 * as problems at the configuration's paths, its bounding box, systems inside the outline and clear
 * of slopes (the wires follow the ceiling), objects inside the outline and under the ceiling. The
 * expected numbers are worked out by hand from the geometry.
 */
import { describe, expect, it } from 'vitest';
import { createConfiguration, type Configuration, type LightSystem, type RoomShape } from '../../../../src/core/model/configuration/configuration';
import { validate } from '../../../../src/core/model/validation/validate';
import { wallFinishes } from '../../../../src/core/model/configuration/roomShape';
import { suspensionPoints, suspensionWireLengths } from '../../../../src/core/model/rails/suspensionPoints';
import { catalog, run } from '../helpers';

/** Issue 29's L: 6 × 5 m, the notch x > 3.5, z > 3. */
const L: RoomShape = {
  outline: [
    [0, 0],
    [6, 0],
    [6, 3],
    [3.5, 3],
    [3.5, 5],
    [0, 5],
  ],
  slopes: [],
  openings: [],
};

const shaped = (shape: Partial<RoomShape> = {}, height = 2.6): Configuration => createConfiguration({ width: 6, depth: 5, height, shape: { ...L, ...shape } });

/** One straight system of `rails` 1 m rails along +x from (x, z). */
function system(x: number, z: number, rails: number, over: Partial<LightSystem> = {}): LightSystem {
  return {
    id: 's1',
    x,
    z,
    rotation: 0,
    suspension: 0.3,
    rails: Array.from({ length: rails }, (_, i) => ({ id: `r${i + 2}`, length: 1, distribution: 'start' as const, modules: [] })),
    joints: Array.from({ length: rails - 1 }, () => ({ connector: 'straight', turn: 0 })),
    feeds: [{ id: 'f9', at: 'start', driver: catalog.feed.defaultDriver }],
    mounting: 'suspended',
    ...over,
  };
}
const withSystem = (c: Configuration, s: LightSystem): Configuration => ({ ...c, systems: [s], nextId: 20 });
const codes = (c: Configuration) => validate(c, catalog).map((p) => `${p.code} ${p.path}`);

describe('a room with a shape in validate()', () => {
  it('the L with a slope and a door is valid; its rules come back at room.shape paths with their codes and params', () => {
    expect(validate(shaped({ slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40 }], openings: [{ wall: 4, offset: 0.8, width: 0.9, sill: 0, height: 2, kind: 'door' }] }), catalog)).toEqual([]);
    const short = validate(
      shaped({
        outline: [
          [0, 0],
          [6, 0],
          [6, 0.05],
          [6, 5],
          [0, 5],
        ],
      }),
      catalog,
    );
    expect(short).toEqual([{ code: 'room-wall-short', path: 'room.shape.outline[1]', message: 'wall 1 (corner 1 to corner 2) is 0.05 m long; each wall must be at least 0.1 m', params: { wall: 1, to: 2, length: 0.05, min: 0.1 } }]);
    expect(codes(shaped({ slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 95 }] }))).toEqual(['room-slope-pitch room.shape.slopes[0].pitch']);
    expect(codes(shaped({ openings: [{ wall: 1, offset: 2.5, width: 1, sill: 0, height: 2, kind: 'door' }] }))).toEqual(['room-opening-beyond-wall room.shape.openings[0].offset']);
    expect(codes(shaped({ openings: [{ wall: 1, offset: 0.5, width: 1, sill: 0, height: 2.7, kind: 'window' }] }))).toEqual(['room-opening-above-ceiling room.shape.openings[0].height']);
  });

  it("the outline's bounding box must be [0, width] × [0, depth]", () => {
    const moved = shaped({ outline: L.outline.map(([x, z]) => [x + 1, z] as const) });
    expect(validate(moved, catalog)).toEqual([
      expect.objectContaining({ code: 'room-shape-bounds', path: 'room.shape.outline', message: "the outline spans x 1 to 7 m and z 0 to 5 m; it must span exactly 0 to the room's 6 m width and 0 to its 5 m depth" }),
    ]);
    expect(codes({ ...shaped(), room: { ...shaped().room, width: 7 } })).toEqual(['room-shape-bounds room.shape.outline']);
  });

  it('per-wall finishes: one per wall, each within the configuration cap', () => {
    expect(codes(shaped({ wallReflectance: [0.5, 0.5] }))).toEqual(['room-wall-reflectance-count room.shape.wallReflectance']);
    expect(codes(shaped({ wallReflectance: [0.5, 0.5, 0.97, 0.5, 0.5, 0.5] }))).toEqual(['reflectance room.shape.wallReflectance[2]']);
  });

  it("wallFinishes: a wall's own finish, else the box wall's it faces most nearly", () => {
    const box = createConfiguration({ width: 4, depth: 3, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.1, east: 0.2, south: 0.3, west: 0.4 } }).room;
    const rect = {
      ...box,
      shape: {
        outline: [
          [0, 0],
          [4, 0],
          [4, 3],
          [0, 3],
        ] as const,
        slopes: [],
        openings: [],
      },
    };
    expect(wallFinishes(rect)).toEqual([0.1, 0.2, 0.3, 0.4]);
    // Clockwise, the same rectangle's walls run west, south, east, north.
    expect(
      wallFinishes({
        ...rect,
        shape: {
          ...rect.shape,
          outline: [
            [0, 0],
            [0, 3],
            [4, 3],
            [4, 0],
          ],
        },
      }),
    ).toEqual([0.4, 0.3, 0.2, 0.1]);
    // The L: its notch walls face south (wall 2) and east (wall 3); a wall's own finish wins.
    expect(wallFinishes({ ...box, shape: L })).toEqual([0.1, 0.2, 0.3, 0.2, 0.3, 0.4]);
    expect(wallFinishes({ ...box, shape: { ...L, wallReflectance: [0.1, 0.7, 0.3, 0.2, 0.3, [0.4, 0.5, 0.6]] } })).toEqual([0.1, 0.7, 0.3, 0.2, 0.3, [0.4, 0.5, 0.6]]);
  });

  it('a system in the notch of the L, or across its inner corner, is outside the room', () => {
    const c = shaped();
    expect(validate(withSystem(c, system(1, 1, 2)), catalog)).toEqual([]);
    const inNotch = validate(withSystem(c, system(4, 4, 1)), catalog);
    expect(inNotch).toEqual([{ code: 'outside-room', path: 'systems[0]', message: "system s1 reaches outside the room's outline", params: { id: 's1' } }]);
    // Across the inner corner (3.5, 3): a rail from (3, 3.2) to (4, 3.2) starts in the room and ends in the notch.
    expect(codes(withSystem(c, system(3, 3.2, 1)))).toEqual(['outside-room systems[0]']);
  });

  it('under a slope: the wires follow the ceiling, and the modules keep the shortest suspension below it along every rail', () => {
    // A slope on wall 0 (z = 0): knee 1.2 m, 45°, so the ceiling is 1.2 + z up to the flat 2.6 m at z = 1.4.
    const c = shaped({ slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 45 }] });
    // A system at z = 2 under the flat part: every wire is its suspension.
    const flat = withSystem(c, system(0.5, 2, 2, { suspension: 0.4 }));
    expect(validate(flat, catalog)).toEqual([]);
    expect(suspensionWireLengths(flat.systems[0], flat.room, catalog).every((w) => Math.abs(w - 0.4) < 1e-12)).toBe(true);
    // At z = 1.2 the modules hang at 2.2 m and the ceiling over the centre line is 2.4 m: fits.
    const under = withSystem(c, system(0.5, 1.2, 2, { suspension: 0.4 }));
    const problems = validate(under, catalog);
    expect(problems).toEqual([]);
    const wires = suspensionWireLengths(under.systems[0], under.room, catalog);
    const points = suspensionPoints(under.systems[0], catalog);
    points.forEach((p, k) => expect(wires[k]).toBeCloseTo(Math.min(2.6, 1.2 + p.plan[1]) - 2.2, 12));
    // At z = 1.0 the ceiling (2.2 m over the centre line) meets the modules at 2.2 m: refused, naming the clearance.
    const tooClose = validate(withSystem(c, system(0.5, 1.0, 2, { suspension: 0.4 })), catalog);
    expect(tooClose).toHaveLength(1);
    expect(tooClose[0]).toMatchObject({ code: 'under-slope', path: 'systems[0].suspension' });
    expect(tooClose[0].message).toMatch(/^system s1 hangs -?0\.0\d+ m under a slope at its closest; the ceiling must stay at least 0\.1 m above its modules$/);
    // A longer suspension lowers the modules to 2.0 m, 0.2 m under the 2.2 m ceiling: fits again.
    expect(validate(withSystem(c, system(0.5, 1.0, 2, { suspension: 0.6 })), catalog).map((p) => p.code)).toEqual([]);
    // Clips need the flat ceiling over the whole footprint.
    const clipped = validate(withSystem(c, system(0.5, 1.0, 2, { mounting: 'surface' })), catalog);
    expect(clipped.map((p) => `${p.code} ${p.path}`)).toEqual(['under-slope systems[0].mounting']);
    expect(validate(withSystem(c, system(0.5, 2, 2, { mounting: 'surface' })), catalog)).toEqual([]);
  });

  it('objects inside the outline and under the ceiling', () => {
    const c = shaped({ slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 45 }] });
    const table = run(c, 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 1.5, z: 3.5 } });
    expect(validate(table, catalog)).toEqual([]);
    const inNotch = { ...table, objects: [{ ...table.objects[0], placement: { on: 'floor' as const, x: 4.8, z: 4 } }] };
    expect(validate(inNotch, catalog)).toEqual([expect.objectContaining({ code: 'object-outside', path: 'objects[0].placement', message: "Dining table reaches outside the room's outline" })]);
    // Near the north wall under the slope (ceiling 1.2 + z): the 0.75 m table fits at z = 0.6.
    const lowSpot = { ...table, objects: [{ ...table.objects[0], placement: { on: 'floor' as const, x: 1.5, z: 0.6 } }] };
    expect(validate(lowSpot, catalog)).toEqual([]);
    // The 2 m shelf (0.35 m deep) at z = 0.5: its near top edge at z = 0.325 is 0.475 m above the 1.525 m ceiling there; at z = 1 the ceiling over that edge is 2.025 m.
    const shelf = (z: number) => run(c, 'addObject', { source: { kind: 'library', item: 'open-shelf' }, placement: { on: 'floor', x: 1.5, z: 3 } }).objects.map((o) => ({ ...o, placement: { on: 'floor' as const, x: 1.5, z } }));
    const tooHigh = validate({ ...c, objects: shelf(0.5), nextId: 9 }, catalog);
    expect(tooHigh).toEqual([expect.objectContaining({ code: 'object-outside', path: 'objects[0].placement', message: 'Open shelf with books reaches 2 m, above the ceiling there (1.525 m under a slope)' })]);
    expect(validate({ ...c, objects: shelf(1), nextId: 9 }, catalog)).toEqual([]);
  });
});
