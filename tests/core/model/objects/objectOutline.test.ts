import { describe, expect, it } from 'vitest';
import { createConfiguration } from '../../../../src/core/model/configuration/configuration';
import { boxPart, composeParts, frustumPart } from '../../../../src/core/model/objects/furniture/meshParts';
import { localOutline, objectOutline, type PlanPolygon } from '../../../../src/core/model/objects/objectOutline';
import { FURNITURE_LIBRARY, furnitureMesh } from '../../../../src/core/model/objects/furniture/furnitureLibrary';
import { run } from '../helpers';

const grey = (): [number, number, number] => [0.5, 0.5, 0.5];
/** Shoelace area (positive counterclockwise in (x, z)). */
const area = (p: PlanPolygon) => p.reduce((s, [x, z], k) => s + x * p[(k + 1) % p.length][1] - p[(k + 1) % p.length][0] * z, 0) / 2;
/** Corners rounded to 1 µm (Float32 vertices), sorted. */
const sorted = (p: PlanPolygon) => [...p].map(([x, z]) => [Math.round(x * 1e5) / 1e5, Math.round(z * 1e5) / 1e5]).sort((a, b) => a[0] - b[0] || a[1] - b[1]);

describe('object outline', () => {
  const room = () => createConfiguration({ width: 6, depth: 5, height: 2.8 });

  it("a table's outline is its top rectangle (the legs lie inside it)", () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 3, z: 2 } });
    const outline = objectOutline(s, 'o1');
    expect(outline.length).toBe(1);
    expect(sorted(outline[0])).toEqual([
      [2.1, 1.55],
      [2.1, 2.45],
      [3.9, 1.55],
      [3.9, 2.45],
    ]);
    expect(area(outline[0])).toBeCloseTo(1.8 * 0.9, 6);
  });

  it('an L-shaped mesh gives an L (six corners, area of the two legs)', () => {
    const l = composeParts([boxPart('a', [0, 0, 0], [2, 0.9, 0.6]), boxPart('a', [0, 0, 0.6], [0.6, 0.9, 1.6])], grey);
    const [poly, ...rest] = localOutline(l, 1);
    expect(rest).toEqual([]);
    expect(sorted(poly)).toEqual([
      [0, 0],
      [0, 1.6],
      [0.6, 0.6],
      [0.6, 1.6],
      [2, 0],
      [2, 0.6],
    ]);
    expect(area(poly)).toBeCloseTo(2 * 0.6 + 0.6 * 1, 6);
    // scaled: the same L, twice the size (cached separately per scale)
    expect(area(localOutline(l, 2)[0])).toBeCloseTo(4 * 1.8, 6);
  });

  it('rotation follows the yaw: turned by 90°, local (x, z) lands at (z, −x) from the origin', () => {
    const s = run(room(), 'addObject', { source: { kind: 'library', item: 'dining-table' }, placement: { on: 'floor', x: 3, z: 2.5 }, yaw: 90 });
    expect(sorted(objectOutline(s, 'o1')[0])).toEqual([
      [2.55, 1.6],
      [2.55, 3.4],
      [3.45, 1.6],
      [3.45, 3.4],
    ]);
    // at 30°, each corner (±0.9, ±0.45) turns to (c·x + s·z, −s·x + c·z)
    const t = run(s, 'rotateObject', { objectId: 'o1', yaw: 30 });
    const [c, sn] = [Math.cos(Math.PI / 6), Math.sin(Math.PI / 6)];
    const expected = [
      [-0.9, -0.45],
      [-0.9, 0.45],
      [0.9, -0.45],
      [0.9, 0.45],
    ].map(([x, z]) => [3 + c * x + sn * z, 2.5 - sn * x + c * z] as const);
    expect(sorted(objectOutline(t, 'o1')[0])).toEqual(sorted(expected));
  });

  it('a round table traces a circle within one grid cell, and a ring keeps its hole', () => {
    const disc = composeParts([frustumPart('top', 0, 0, 0, 0.7, 0.5, 0.5, 64)], grey);
    const [poly] = localOutline(disc, 1);
    for (const [x, z] of poly) expect(Math.abs(Math.hypot(x, z) - 0.5)).toBeLessThan(0.015);
    // area of the 64-gon, 0.5·64·r²·sin(2π/64) = 0.7844, within the grid's resolution
    expect(Math.abs(area(poly) - 0.5 * 64 * 0.25 * Math.sin((2 * Math.PI) / 64))).toBeLessThan(0.02);
    // four bars around a 1 m square hole: an outer contour (counterclockwise) and a hole (clockwise)
    const frame = composeParts([boxPart('f', [0, 0, 0], [2, 0.1, 0.5]), boxPart('f', [0, 0, 1.5], [2, 0.1, 2]), boxPart('f', [0, 0, 0.5], [0.5, 0.1, 1.5]), boxPart('f', [1.5, 0, 0.5], [2, 0.1, 1.5])], grey);
    const areas = localOutline(frame, 1)
      .map(area)
      .sort((a, b) => a - b);
    expect(areas[0]).toBeCloseTo(-1, 6);
    expect(areas[1]).toBeCloseTo(4, 6);
  });

  it('every library item has an outline inside its stated footprint, filling most of its box', () => {
    for (const item of FURNITURE_LIBRARY) {
      const polys = localOutline(furnitureMesh(item.id), 1);
      const total = polys.reduce((sum, p) => sum + area(p), 0);
      const box = item.width * item.depth;
      expect(total).toBeLessThanOrEqual(box + 1e-6);
      // round items (plant) fill π/4 of their box; everything else more than half
      expect(total).toBeGreaterThan(0.5 * box);
      for (const p of polys) for (const [x, z] of p) expect(Math.abs(x) <= item.width / 2 + 1e-6 && z >= -item.depth / 2 - 1e-6 && z <= item.depth + 1e-6).toBe(true);
    }
  });
});
