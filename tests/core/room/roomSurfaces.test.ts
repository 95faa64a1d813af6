import { describe, expect, it } from 'vitest';
import { BOX_FACES } from '../../../src/reference/boxGeometry';
import { boxRoomInput, BOX_WALL_NAMES } from '../../../src/core/room/boxRoom';
import { ceilingHeightAt, pointInsideRoom } from '../../../src/core/room/ceilingHeightAt';
import { keepHalfPlane } from '../../../src/core/room/keepHalfPlane';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import { doubleSignedArea } from '../../../src/core/room/planPolygon';
import { roomSurfaces, type Point3, type RoomSurface } from '../../../src/core/room/roomSurfaces';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { attic, gable, issueExample, L_OUTLINE, plainReflectance, U_OUTLINE } from './roomFixtures';

const byId = (surfaces: RoomSurface[], id: string): RoomSurface => {
  const s = surfaces.find((x) => x.id === id);
  if (!s) throw new Error(`no surface ${id}`);
  return s;
};
const sortedPoints = (ps: readonly Point3[]) => ps.map((p) => p.map((v) => Math.round(v * 1e9) / 1e9).join(',')).sort();

/**
 * A closed polyhedron's faces satisfy Σ A·n_out = 0, and its volume is (1/3) Σ A (n_out · p) for
 * any point p of each face (divergence theorem). Openings are part of the boundary here.
 */
function closure(surfaces: RoomSurface[]): { sum: Point3; volume: number } {
  const sum: Point3 = [0, 0, 0];
  let volume = 0;
  for (const s of surfaces) {
    const gross = s.area + s.openings.reduce((a, o) => a + o.area, 0);
    for (let k = 0; k < 3; k++) sum[k] += gross * s.outward[k];
    const p = s.polygons[0][0];
    volume += (gross * (s.outward[0] * p[0] + s.outward[1] * p[1] + s.outward[2] * p[2])) / 3;
  }
  return { sum, volume };
}

describe('room geometry', () => {
  it("the rectangle outline is today's box: the same six faces, names and inward normals", () => {
    const box = { width: 4, height: 2.6, depth: 3, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, east: 0.6, south: 0.4, west: [0.1, 0.2, 0.3] as [number, number, number] } };
    const room = normaliseRoom(boxRoomInput(box));
    expect(room.reversed).toBe(false);
    const surfaces = roomSurfaces(room);
    expect(surfaces.map((s) => s.id)).toEqual(['floor', 'ceiling', 'wall-0', 'wall-1', 'wall-2', 'wall-3']);
    const extent = [box.width, box.height, box.depth];
    for (const face of BOX_FACES) {
      const id = face.name === 'floor' || face.name === 'ceiling' ? face.name : `wall-${BOX_WALL_NAMES.indexOf(face.name as never)}`;
      const s = byId(surfaces, id);
      // The face's four corners: u and v over their extents, the normal axis at 0 or the extent.
      const corners: Point3[] = [];
      for (const [u, v] of [
        [0, 0],
        [1, 0],
        [1, 1],
        [0, 1],
      ]) {
        const p: Point3 = [0, 0, 0];
        p[face.axis] = face.side === 0 ? 0 : extent[face.axis];
        p[face.uAxis] = u * extent[face.uAxis];
        p[face.vAxis] = v * extent[face.vAxis];
        corners.push(p);
      }
      expect(s.polygons).toHaveLength(1);
      expect(sortedPoints(s.polygons[0])).toEqual(sortedPoints(corners));
      expect(s.inward.map((v) => v + 0)).toEqual(face.normal);
      expect(s.area).toBeCloseTo(extent[face.uAxis] * extent[face.vAxis], 12);
      const expected = box.reflectance[face.name as keyof typeof box.reflectance];
      expect(s.reflectance).toEqual(typeof expected === 'number' ? [expected, expected, expected] : expected);
    }
  });

  it('the L: floor and ceiling of 25 m², six walls of perimeter × height, closed', () => {
    const surfaces = roomSurfaces(normaliseRoom({ outline: L_OUTLINE, height: 2.6, reflectance: plainReflectance }));
    expect(byId(surfaces, 'floor').area).toBeCloseTo(25, 12);
    expect(byId(surfaces, 'ceiling').area).toBeCloseTo(25, 12);
    const walls = surfaces.filter((s) => s.kind === 'wall');
    expect(walls.map((w) => w.area)).toEqual([6, 3, 2.5, 2, 3.5, 5].map((l) => expect.closeTo(l * 2.6, 12)));
    const { sum, volume } = closure(surfaces);
    for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-12);
    expect(volume).toBeCloseTo(25 * 2.6, 10);
  });

  it('the attic: slope and flat parts, a pentagon gable end, the ceiling height and the volume', () => {
    const room = normaliseRoom(attic);
    const surfaces = roomSurfaces(room);
    const t = Math.tan((40 * Math.PI) / 180);
    const z0 = (2.6 - 1.2) / t; // where the slope meets the flat ceiling
    expect(ceilingHeightAt(room, 1, 0.5)).toBeCloseTo(1.2 + 0.5 * t, 12);
    expect(ceilingHeightAt(room, 1, 5)).toBe(2.6);
    expect(byId(surfaces, 'slope-0').area).toBeCloseTo((4 * z0) / Math.cos((40 * Math.PI) / 180), 12);
    expect(byId(surfaces, 'ceiling').area).toBeCloseTo(4 * (6 - z0), 12);
    expect(byId(surfaces, 'wall-0').area).toBeCloseTo(4 * 1.2, 12);
    const east = byId(surfaces, 'wall-1');
    expect(east.polygons[0]).toHaveLength(5);
    expect(east.area).toBeCloseTo(6 * 2.6 - 0.5 * z0 * 1.4, 12);
    // The slope's inward normal points down and away from its wall (+z).
    const slope = byId(surfaces, 'slope-0');
    expect(slope.inward[1]).toBeCloseTo(-Math.cos((40 * Math.PI) / 180), 12);
    expect(slope.inward[2]).toBeCloseTo(Math.sin((40 * Math.PI) / 180), 12);
    const { sum, volume } = closure(surfaces);
    for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-12);
    expect(volume).toBeCloseTo(4 * (6 * 2.6 - 0.5 * z0 * 1.4), 10);
    expect(pointInsideRoom(room, [2, 1.3, 0.2])).toBe(true);
    expect(pointInsideRoom(room, [2, 1.6, 0.2])).toBe(false); // above the slope
    expect(pointInsideRoom(room, [2, 2.6, 0.2])).toBe(false);
    expect(pointInsideRoom(room, [2, -0.01, 3])).toBe(false);
  });

  it('a gable wall under two slopes is a pentagon; the flat ceiling above the ridge is left out', () => {
    const surfaces = roomSurfaces(normaliseRoom(gable));
    expect(surfaces.map((s) => s.id)).toEqual(['floor', 'slope-0', 'slope-1', 'wall-0', 'wall-1', 'wall-2', 'wall-3']);
    const east = byId(surfaces, 'wall-1');
    // In the east wall's frame (u from (5, 0) toward (5, 4), v up): (0,0), (4,0), (4,1), ridge (2,3), (0,1).
    expect(sortedPoints(east.polygons2d[0].map(([u, v]): Point3 => [u, v, 0]))).toEqual(
      sortedPoints([
        [0, 0, 0],
        [4, 0, 0],
        [4, 1, 0],
        [2, 3, 0],
        [0, 1, 0],
      ]),
    );
    expect(east.area).toBeCloseTo(4 + 4, 12); // 4 × 1 below the knee, a 4 × 2 triangle above
    expect(byId(surfaces, 'slope-0').area).toBeCloseTo(5 * 2 * Math.SQRT2, 12);
    const { sum, volume } = closure(surfaces);
    for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-12);
    expect(volume).toBeCloseTo(5 * 8, 10);
  });

  it("the L with the issue's slope and door: inside test, a hole in wall 4, closed", () => {
    const room = normaliseRoom(issueExample);
    const surfaces = roomSurfaces(room);
    const wall4 = byId(surfaces, 'wall-4');
    expect(wall4.openings).toHaveLength(1);
    expect(wall4.openings[0].area).toBeCloseTo(1.8, 12);
    // Wall 4 runs (3.5, 5) → (0, 5): the door spans x from 2.7 down to 1.8 at z = 5, y 0..2.
    expect(sortedPoints(wall4.openings[0].polygon)).toEqual(
      sortedPoints([
        [2.7, 0, 5],
        [1.8, 0, 5],
        [1.8, 2, 5],
        [2.7, 2, 5],
      ]),
    );
    expect(wall4.area).toBeCloseTo(3.5 * 2.6 - 1.8, 12);
    expect(pointInsideRoom(room, [5, 1.5, 2])).toBe(true);
    expect(pointInsideRoom(room, [5, 1.5, 4])).toBe(false); // in the notch
    expect(pointInsideRoom(room, [6, 1, 1])).toBe(true); // on the east wall
    const { sum } = closure(surfaces);
    for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-12);
  });

  it('a reversed outline gives the same surfaces, walls named as written, openings in the same place', () => {
    const reversed: RoomInput = {
      ...issueExample,
      outline: [L_OUTLINE[0], ...L_OUTLINE.slice(1).reverse()],
      slopes: [{ wall: 5, kneeHeight: 1.2, pitch: 40 }],
      // Input wall 1 of the reversed outline runs (0, 5) → (3.5, 5): the same door is 1.8 m from its start.
      openings: [{ wall: 1, offset: 1.8, width: 0.9, sill: 0, height: 2, kind: 'door' }],
      reflectance: { ...plainReflectance, walls: [0.1, 0.2, 0.3, 0.4, 0.5, 0.6] },
    };
    const a = roomSurfaces(normaliseRoom(issueExample));
    const roomB = normaliseRoom(reversed);
    expect(roomB.reversed).toBe(true);
    const b = roomSurfaces(roomB);
    // Input wall i of the reversed outline is wall 5 − i of the original.
    for (const s of a) {
      const id = s.kind === 'wall' ? `wall-${5 - s.inputIndex}` : s.id;
      const t = byId(b, id);
      expect(t.area).toBeCloseTo(s.area, 12);
      expect(sortedPoints(t.polygons.flat())).toEqual(sortedPoints(s.polygons.flat()));
      expect(t.openings.map((o) => sortedPoints(o.polygon))).toEqual(s.openings.map((o) => sortedPoints(o.polygon)));
    }
    expect(byId(b, 'wall-2').reflectance).toEqual([0.3, 0.3, 0.3]);
  });

  it('a slope over a U splits the flat ceiling into two pieces', () => {
    const room = normaliseRoom({ outline: U_OUTLINE, height: 2.5, slopes: [{ wall: 0, kneeHeight: 1, pitch: 45 }], reflectance: plainReflectance });
    const surfaces = roomSurfaces(room);
    // The slope reaches 2.5 m at z = 1.5: the flat ceiling is the two arms beyond, 2 × 2.5 m each.
    const ceiling = byId(surfaces, 'ceiling');
    expect(ceiling.polygons).toHaveLength(2);
    expect(ceiling.area).toBeCloseTo(10, 12);
    expect(byId(surfaces, 'slope-0').area).toBeCloseTo(6 * 1.5 * Math.SQRT2, 12);
    const { sum } = closure(surfaces);
    for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-12);
  });

  it('a slope whose top edge runs exactly through corners of an L (z = 3): slope over the east wing and a strip, flat over the rest', () => {
    for (const outline of [L_OUTLINE, [L_OUTLINE[0], ...L_OUTLINE.slice(1).reverse()]]) {
      const wall = outline === L_OUTLINE ? 0 : 5;
      const pitch = (Math.atan(1.4 / 3) * 180) / Math.PI; // 1.2 m + 3 m × 1.4/3 = 2.6 m at z = 3
      const surfaces = roomSurfaces(normaliseRoom({ outline, height: 2.6, slopes: [{ wall, kneeHeight: 1.2, pitch }], reflectance: plainReflectance }));
      const slope = surfaces.find((s) => s.kind === 'slope')!;
      const ceiling = byId(surfaces, 'ceiling');
      expect(slope.area * -slope.inward[1]).toBeCloseTo(18, 9);
      expect(ceiling.area).toBeCloseTo(7, 9);
      const { sum } = closure(surfaces);
      for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-9);
    }
  });

  it('keepHalfPlane cuts a U into its two arms, each of positive orientation', () => {
    const pieces = keepHalfPlane(U_OUTLINE, { a: 0, b: -1, c: 2 }); // z > 2
    expect(pieces).toHaveLength(2);
    for (const p of pieces) expect(doubleSignedArea(p) / 2).toBeCloseTo(4, 12);
    expect(keepHalfPlane(U_OUTLINE, { a: 0, b: 1, c: -2 }).map((p) => doubleSignedArea(p) / 2)).toEqual([expect.closeTo(24 - 2 * 2.5 - 8, 12)]);
    expect(keepHalfPlane(U_OUTLINE, { a: 0, b: 1, c: 1 })).toEqual([]);
  });
});
