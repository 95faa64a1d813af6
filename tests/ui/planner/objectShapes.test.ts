import { describe, expect, it } from 'vitest';
import { createConfiguration, type Configuration, type ObjectPlacement } from '../../../src/core/model/configuration/configuration';
import { boxPart, composeParts } from '../../../src/core/model/objects/furniture/meshParts';
import type { TriangleMesh } from '../../../src/core/mesh/triangleMesh';
import { insidePolygon, objectAt } from '../../../src/ui/planner/planHitTest';
import { OUTLINE_CELL, objectPolygons } from '../../../src/ui/planner/objectShapes';
import type { PlanPoint } from '../../../src/ui/planner/viewTransform';

/** Shoelace area of loops, even-odd: holes (the opposite winding) subtract. */
function area(loops: PlanPoint[][]): number {
  return Math.abs(
    loops.reduce(
      (sum, l) =>
        sum +
        l.reduce((s, p, i) => {
          const q = l[(i + 1) % l.length];
          return s + p.x * q.z - q.x * p.z;
        }, 0) /
          2,
      0,
    ),
  );
}

function bounds(loops: PlanPoint[][]) {
  const pts = loops.flat();
  return { minX: Math.min(...pts.map((p) => p.x)), maxX: Math.max(...pts.map((p) => p.x)), minZ: Math.min(...pts.map((p) => p.z)), maxZ: Math.max(...pts.map((p) => p.z)) };
}

/** A configuration holding one imported mesh as object 'o1'. */
function withMesh(mesh: TriangleMesh, placement: ObjectPlacement = { on: 'floor', x: 2, z: 2 }, yaw = 0, scale = 1): Configuration {
  return { ...createConfiguration(), objects: [{ id: 'o1', source: { kind: 'imported', mesh: 'i1' }, placement, yaw, scale, finishes: {} }], importedMeshes: { i1: { name: 'test.obj', mesh, units: 'm' } } };
}

/** A library item's outline from above at scale 1 and yaw 0, about its origin (placed alone in a large room). */
function libraryItemOutline(itemId: string): PlanPoint[][] {
  const id = 'alone';
  const config: Configuration = {
    ...createConfiguration({ width: 30, depth: 30, height: 8 }),
    objects: [{ id, source: { kind: 'library', item: itemId }, placement: { on: 'floor', x: 15, z: 15 }, yaw: 0, scale: 1, finishes: {} }],
  };
  return objectPolygons(config, id).map((poly) => poly.map((p) => ({ x: p.x - 15, z: p.z - 15 })));
}

const grey = () => [0.5, 0.5, 0.5] as [number, number, number];

describe('object outlines seen from above', () => {
  it("a dining table's outline is its 180 × 90 cm top (the legs are under it): one loop, area and bounds to the trace's 5 mm cell", () => {
    const loops = libraryItemOutline('dining-table');
    expect(loops).toHaveLength(1);
    const b = bounds(loops);
    for (const [got, want] of [
      [b.minX, -0.9],
      [b.maxX, 0.9],
      [b.minZ, -0.45],
      [b.maxZ, 0.45],
    ])
      expect(Math.abs(got - want)).toBeLessThanOrEqual(OUTLINE_CELL + 1e-9);
    // A rectangle traced on cells aligned with it: exact up to float noise; simplified to its four corners.
    expect(area(loops)).toBeCloseTo(1.8 * 0.9, 6);
    expect(loops[0]).toHaveLength(4);
  });

  it('an L-shaped mesh gives an L (area 0.36 m², the inner corner outside)', () => {
    const mesh = composeParts([boxPart('a', [0, 0, 0], [1, 0.5, 0.2]), boxPart('b', [0, 0, 0], [0.2, 0.5, 1])], grey);
    const config = withMesh(mesh);
    const loops = objectPolygons(config, 'o1');
    expect(area(loops)).toBeCloseTo(0.36, 6);
    expect(objectAt(config, 2.9, 2.1, 0)).toBe('o1');
    expect(objectAt(config, 2.1, 2.9, 0)).toBe('o1');
    expect(objectAt(config, 2.6, 2.6, 0)).toBeUndefined();
  });

  it('a frame (four bars round a hole) gives two loops; the hole is not part of the object', () => {
    const mesh = composeParts([boxPart('f', [0, 0, 0], [1, 0.1, 0.1]), boxPart('f', [0, 0, 0.9], [1, 0.1, 1]), boxPart('f', [0, 0, 0.1], [0.1, 0.1, 0.9]), boxPart('f', [0.9, 0, 0.1], [1, 0.1, 0.9])], grey);
    const config = withMesh(mesh);
    const loops = objectPolygons(config, 'o1');
    expect(loops).toHaveLength(2);
    expect(area(loops)).toBeCloseTo(1 - 0.64, 6);
    expect(objectAt(config, 2.5, 2.5, 0)).toBeUndefined();
    expect(objectAt(config, 2.05, 2.5, 0)).toBe('o1');
  });

  it('the outline follows the yaw and scale (world = T·Ry(yaw)·S·local): a table turned 90° at scale 1.1 is 0.99 m along x and 1.98 m along z', () => {
    const base = createConfiguration();
    const config: Configuration = { ...base, objects: [{ id: 'o1', source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 2.5, z: 2 }, yaw: 90, scale: 1.1, finishes: {} }] };
    const b = bounds(objectPolygons(config, 'o1'));
    expect(b.maxX - b.minX).toBeCloseTo(0.99, 6);
    expect(b.maxZ - b.minZ).toBeCloseTo(1.98, 6);
    expect((b.minX + b.maxX) / 2).toBeCloseTo(2.5, 6);
    expect((b.minZ + b.maxZ) / 2).toBeCloseTo(2, 6);
    // 30°: the rotated rectangle's corners, not an axis-aligned box (a point just off the long edge's middle is outside).
    const turned: Configuration = { ...config, objects: [{ ...config.objects[0], yaw: 30, scale: 1 }] };
    const loops = objectPolygons(turned, 'o1');
    expect(area(loops)).toBeCloseTo(1.62, 2);
    const c = Math.cos(Math.PI / 6);
    const s = Math.sin(Math.PI / 6);
    // Local (0, 0.46) (just past the 0.45 m half depth) placed: x = 2.5 + 0.46 s, z = 2 + 0.46 c.
    expect(loops.some((l) => insidePolygon(l, 2.5 + 0.46 * s, 2 + 0.46 * c))).toBe(false);
    expect(loops.some((l) => insidePolygon(l, 2.5 + 0.44 * s, 2 + 0.44 * c))).toBe(true);
  });

  it('a picture on the north wall is a 80 × 3 cm strip against the wall', () => {
    const config: Configuration = { ...createConfiguration(), objects: [{ id: 'o1', source: { kind: 'library', item: 'picture' }, placement: { on: 'wall', wall: 'north', u: 2, y: 1.55 }, yaw: 0, scale: 1, finishes: {} }] };
    const b = bounds(objectPolygons(config, 'o1'));
    expect(b.minX).toBeCloseTo(1.6, 6);
    expect(b.maxX).toBeCloseTo(2.4, 6);
    expect(b.minZ).toBeCloseTo(0, 6);
    expect(b.maxZ).toBeCloseTo(0.03, 6);
  });

  it('every library item traces to closed loops whose bounds are its stated width and depth (round parts within a cell)', async () => {
    const { FURNITURE_LIBRARY } = await import('../../../src/core/model/objects/furniture/furnitureLibrary');
    for (const item of FURNITURE_LIBRARY.filter((i) => i.mount === 'floor')) {
      const b = bounds(libraryItemOutline(item.id));
      expect(Math.abs(b.maxX - b.minX - item.width), item.id).toBeLessThanOrEqual(2 * OUTLINE_CELL);
      expect(Math.abs(b.maxZ - b.minZ - item.depth), item.id).toBeLessThanOrEqual(2 * OUTLINE_CELL);
    }
  });
});
