/**
 * The plan icon of a module type with an L3D body (docs/gldf.md "L3D in the plan"): the convex
 * hull of the body seen from above, aimed straight down, turned with the rail. Checked against the
 * hand-made spot's parts (buildL3dSpot.ts): the yoke's 84 mm width along the rail, the head's
 * 35 mm radius and the barn door at 45° reaching 64 mm across it; every vertex of the body inside
 * the hull; the hull loaded through the plan's footprint source (one fetch, a lazy chunk) and drawn
 * by PlanSvg in place of the rectangle.
 */
import { describe, expect, it } from 'vitest';
import { poseL3dBody } from '../../../src/engines/view/luminaires/l3dBody';
import { convexHull, l3dPlanOutline } from '../../../src/engines/view/luminaires/l3dPlanOutline';
import { readL3dBody } from '../../../src/engines/view/luminaires/readL3dBody';
import { createFootprintSource } from '../../../src/ui/planner/footprintSource';
import { modelSymbolPoints } from '../../../src/ui/planner/modelSymbol';
import { spotL3d } from '../../core/gldf/buildL3dSpot';

const body = readL3dBody(spotL3d(), 'geo/track-spot.l3d');

/** Signed area of a closed polygon (positive: counterclockwise in (x, z)). */
const area = (p: readonly [number, number][]) => p.reduce((s, a, i) => s + (a[0] * p[(i + 1) % p.length][1] - p[(i + 1) % p.length][0] * a[1]) / 2, 0);

describe('the plan outline of an L3D body', () => {
  it('convexHull: a square with points inside and on its edges gives its four corners, counterclockwise', () => {
    const hull = convexHull([
      [0, 0],
      [1, 0],
      [0.5, 0],
      [1, 1],
      [0, 1],
      [0.3, 0.6],
      [0.5, 0.5],
      [0, 0],
    ]);
    expect(hull).toEqual([
      [0, 0],
      [1, 0],
      [1, 1],
      [0, 1],
    ]);
    expect(area(hull)).toBe(1);
  });

  it('is the hull of the spot from above: yoke ±42 mm along the rail, head ±35 mm across, the barn door to −64 mm', () => {
    const hull = l3dPlanOutline(body);
    const xs = hull.map((p) => p[0]);
    const zs = hull.map((p) => p[1]);
    expect(Math.min(...xs)).toBeCloseTo(-0.042, 6);
    expect(Math.max(...xs)).toBeCloseTo(0.042, 6);
    expect(Math.max(...zs)).toBeCloseTo(0.035, 6);
    // Hinged at z −35 mm, 41 mm of door at 45°: −(0.035 + 0.041·cos 45°).
    expect(Math.min(...zs)).toBeCloseTo(-(0.035 + 0.041 * Math.SQRT1_2), 6);
    expect(area(hull)).toBeGreaterThan(0);
    // Every vertex of the posed body is inside or on the hull (each edge has it on its left, 1e-9 m²).
    const inside = (x: number, z: number) =>
      hull.every((a, i) => {
        const b = hull[(i + 1) % hull.length];
        return (b[0] - a[0]) * (z - a[1]) - (b[1] - a[1]) * (x - a[0]) >= -1e-9;
      });
    for (const p of poseL3dBody(body, body.reference).parts.filter((q) => q.role === 'housing')) {
      for (let i = 0; i < p.positions.length; i += 3) expect(inside(p.positions[i], p.positions[i + 2])).toBe(true);
    }
  });

  it('turns with the rail: a rail at 90° takes the x along the rail to plan −z', () => {
    expect(modelSymbolPoints([[0.1, 0]], [2, 3], 90).map((p) => p.map((v) => Number(v.toFixed(12))))).toEqual([[2, 2.9]]);
    expect(modelSymbolPoints([[0, 0.1]], [2, 3], 90).map((p) => p.map((v) => Number(v.toFixed(12))))).toEqual([[2.1, 3]]);
  });

  it('the plan loads it through the footprint source: one fetch from the asset folder, read in a lazy chunk (PlanSvg draws it: e2e/gldfCatalog.spec.ts)', async () => {
    const fetched: string[] = [];
    const source = createFootprintSource('shop/', async (input) => {
      fetched.push(String(input));
      return new Response(new Uint8Array(spotL3d()).buffer);
    });
    source.requestOutlines(['geo/track-spot.l3d']);
    source.requestOutlines(['geo/track-spot.l3d']);
    await new Promise<void>((resolve) => {
      const off = source.subscribe(() => {
        if (source.outline('geo/track-spot.l3d') !== undefined) {
          off();
          resolve();
        }
      });
    });
    expect(fetched).toEqual(['shop/geo/track-spot.l3d']);
    const hull = source.outline('geo/track-spot.l3d')!;
    expect(hull).toEqual(l3dPlanOutline(body));
  });
});
