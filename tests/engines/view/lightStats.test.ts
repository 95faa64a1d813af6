import { describe, expect, it } from 'vitest';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { AUTO_EXPOSURE_KEY, autoExposure } from '../../../src/engines/view/autoExposure';
import { floorStats, floorUnderObjects, statsOf, workPlaneStats } from '../../../src/engines/view/lightStats';
import { luxScaleTop } from '../../../src/engines/view/luxScaleTop';
import { isotropic, uniformRoom } from '../bake/bakeTestKit';
import { boxMesh } from '../bake/objects/objectFixtures';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';

describe('illuminance statistics', () => {
  it('statsOf: average, min, max and U0 = Emin/Ē by hand', () => {
    expect(statsOf([100, 200, 300, 400])).toEqual({ avg: 250, min: 100, max: 400, u0: 0.4, points: 4 });
    expect(statsOf([0, 0])).toEqual({ avg: 0, min: 0, max: 0, u0: 0, points: 2 });
    expect(statsOf([])).toEqual({ avg: 0, min: 0, max: 0, u0: 0, points: 0 });
  });

  it('floor statistics read photometric Y of the RGB floor map', () => {
    const lit = emptyLitMaps(surfaceLayouts({ width: 2, height: 2.5, depth: 1 }, 0.5, 64));
    const f = lit.maps.floor.total; // 4 × 2 texels
    for (let i = 0; i < f.length / 3; i++) f.set(i < 4 ? [100, 100, 100] : [300, 0, 0], i * 3);
    const s = floorStats(lit);
    const red = 300 * 0.2126;
    expect(s.points).toBe(8);
    expect(s.min).toBeCloseTo(red, 4);
    expect(s.max).toBeCloseTo(100, 4);
    expect(s.avg).toBeCloseTo((400 + 4 * red) / 8, 4);
  });

  it('work plane, no indirect light: equals the point-source law E = I·h/d³ at every grid point (CIE 171:2006 §5.2)', () => {
    const I = 1000;
    const lamp: [number, number, number] = [1.2, 2.5, 1.7];
    const scene: BakeScene = { room: uniformRoom(3, 2.8, 3.5, 0), luminaires: [{ photometry: isotropic(I), position: lamp, yaw: 0, pitch: 0, roll: 0 }] };
    const lit = emptyLitMaps(surfaceLayouts(scene.room, 0.1, 64));
    const h = 0.8;
    const plane = workPlaneStats(scene, lit, h, 0.25);
    expect(plane.nx).toBe(12);
    expect(plane.nz).toBe(14);
    let worst = 0;
    for (let k = 0; k < plane.nz; k++) {
      for (let i = 0; i < plane.nx; i++) {
        const dx = (i + 0.5) * 0.25 - lamp[0];
        const dz = (k + 0.5) * 0.25 - lamp[2];
        const dy = lamp[1] - h;
        const d = Math.hypot(dx, dy, dz);
        worst = Math.max(worst, Math.abs(plane.values[k * plane.nx + i] - (I * dy) / d ** 3) / ((I * dy) / d ** 3));
      }
    }
    expect(worst).toBeLessThan(1e-6);
    expect(plane.max).toBeLessThanOrEqual(I / (lamp[1] - h) ** 2);
    expect(plane.u0).toBeCloseTo(plane.min / plane.avg, 12);
  });

  it('work plane with objects: an opaque plate between lamp and plane leaves exactly its shadow dark, the rest is I·h/d³', () => {
    const I = 1000;
    const lamp: [number, number, number] = [1.5, 2.5, 1.75];
    // A 1 × 1 m plate, 2 cm thick, its underside at 1.59 m, centred under the lamp.
    const plate = { id: 'plate', mesh: boxMesh(1, 0.02, 1), position: [1.5, 1.59, 1.75] as [number, number, number], yaw: 0, scale: 1 };
    const scene: BakeScene = { room: uniformRoom(3, 2.8, 3.5, 0), luminaires: [{ photometry: isotropic(I), position: lamp, yaw: 0, pitch: 0, roll: 0 }], objects: [plate] };
    const lit = emptyLitMaps(surfaceLayouts(scene.room, 0.1, 64));
    const h = 0.8;
    const plane = workPlaneStats(scene, lit, h, 0.1, {}, prepareObjects([plate], { texelSize: 0.1 }));
    let shadowed = 0;
    let checked = 0;
    for (let k = 0; k < plane.nz; k++) {
      for (let i = 0; i < plane.nx; i++) {
        const p = [(i + 0.5) * 0.1, h, (k + 0.5) * 0.1];
        // Where the segment to the lamp crosses the plate's two faces (y = 1.59 and 1.61).
        const cross = (y: number) => [0, 2].map((a) => p[a] + ((y - h) / (lamp[1] - h)) * (lamp[a] - p[a]));
        const inside = (q: number[], m: number) => Math.abs(q[0] - 1.5) < 0.5 - m && Math.abs(q[1] - 1.75) < 0.5 - m;
        const [lo, hi] = [cross(1.59), cross(1.61)];
        const clear = !inside(lo, -0.04) && !inside(hi, -0.04);
        const e = plane.values[k * plane.nx + i];
        if (inside(lo, 0.02) && inside(hi, 0.02)) {
          expect(e).toBe(0);
          shadowed++;
        } else if (clear) {
          const d = Math.hypot(p[0] - lamp[0], lamp[1] - h, p[2] - lamp[2]);
          expect(Math.abs(e - (I * (lamp[1] - h)) / d ** 3) / ((I * (lamp[1] - h)) / d ** 3)).toBeLessThan(1e-6);
          checked++;
        }
      }
    }
    // The shadow of a 1 m plate 0.91 m under the lamp on a plane 1.7 m under it: about 1.87 m square.
    expect(shadowed).toBeGreaterThan(250);
    expect(checked).toBeGreaterThan(500);
  });

  it("work plane adds the floor's indirect illuminance (total − direct) at the same plan point", () => {
    const scene: BakeScene = { room: uniformRoom(2, 2.8, 2, 0.5), luminaires: [] };
    const lit = emptyLitMaps(surfaceLayouts(scene.room, 0.1, 64));
    lit.maps.floor.total.fill(40);
    lit.maps.floor.direct.fill(15);
    const plane = workPlaneStats(scene, lit, 0.75, 0.5);
    expect(plane.min).toBeCloseTo(25, 4);
    expect(plane.max).toBeCloseTo(25, 4);
  });
});

describe('automatic exposure', () => {
  it('maps a uniformly lit room to the key value: exposure = key·π/(ρE)', () => {
    const lit = emptyLitMaps(surfaceLayouts({ width: 3, height: 2.5, depth: 4 }, 0.25, 64));
    for (const n of SURFACE_NAMES) lit.maps[n].total.fill(200);
    const rho = Object.fromEntries(SURFACE_NAMES.map((n) => [n, [0.5, 0.5, 0.5]])) as Record<SurfaceName, Rgb>;
    expect(autoExposure(lit, rho)).toBeCloseTo((AUTO_EXPOSURE_KEY * Math.PI) / (0.5 * 200), 9);
  });

  it('is the log (geometric) average: half the area at 4× the light gives 2× the mean luminance', () => {
    const lit = emptyLitMaps(surfaceLayouts({ width: 2, height: 2, depth: 2 }, 0.5, 64));
    const rho = Object.fromEntries(SURFACE_NAMES.map((n) => [n, [1, 1, 1]])) as Record<SurfaceName, Rgb>;
    SURFACE_NAMES.forEach((n, i) => lit.maps[n].total.fill(i < 3 ? 100 : 400));
    expect(autoExposure(lit, rho)).toBeCloseTo((AUTO_EXPOSURE_KEY * Math.PI) / 200, 9);
  });

  it('a dark room gets exposure 1, never Infinity', () => {
    const lit = emptyLitMaps(surfaceLayouts({ width: 2, height: 2, depth: 2 }, 0.5, 64));
    const rho = Object.fromEntries(SURFACE_NAMES.map((n) => [n, [0.5, 0.5, 0.5]])) as Record<SurfaceName, Rgb>;
    expect(autoExposure(lit, rho)).toBe(1);
  });
});

describe('false-colour scale top', () => {
  it('is the 99th percentile (one 1/16-decade bin above it), not a tiny hot spot', () => {
    const lit = emptyLitMaps(surfaceLayouts({ width: 2, height: 2, depth: 2 }, 0.1, 64));
    let n = 0;
    for (const name of SURFACE_NAMES) {
      const m = lit.maps[name].total;
      for (let i = 0; i < m.length; i += 3) m.fill(n++ % 200 === 0 ? 1e5 : 300, i, i + 3); // 0.5 % hot texels
    }
    const top = luxScaleTop(lit);
    expect(top).toBeGreaterThanOrEqual(300);
    expect(top).toBeLessThan(300 * 10 ** (1 / 16) * 1.0001);
    expect(luxScaleTop(emptyLitMaps(surfaceLayouts({ width: 1, height: 1, depth: 1 }, 0.5, 8)))).toBeLessThan(0.01);
  });
});

describe('floor statistics leave out the floor under furniture that stands on it', () => {
  // A 3 × 3.5 m floor at 0.1 m texels (30 × 35); texel (i, j) lit with a grey of 10 + i + 100·j lux,
  // so every texel has its own value and a wrongly kept or dropped texel changes the numbers.
  const room = uniformRoom(3, 2.8, 3.5, 0);
  const litFloor = () => {
    const lit = emptyLitMaps(surfaceLayouts(room, 0.1, 64));
    const f = lit.layouts.floor;
    for (let j = 0; j < f.height; j++) for (let i = 0; i < f.width; i++) lit.maps.floor.total.fill(10 + i + 100 * j, (j * f.width + i) * 3, (j * f.width + i) * 3 + 3);
    return lit;
  };
  /** Stats by hand over the texels whose centre (x, z) `hidden` does not claim. */
  const byHand = (hidden: (x: number, z: number) => boolean) => {
    const kept: number[] = [];
    for (let j = 0; j < 35; j++) for (let i = 0; i < 30; i++) if (!hidden((i + 0.5) * 0.1, (j + 0.5) * 0.1)) kept.push(10 + i + 100 * j);
    return { kept, avg: kept.reduce((a, b) => a + b, 0) / kept.length, min: Math.min(...kept), max: Math.max(...kept) };
  };

  it('a 1 × 0.5 × 1 m box on the floor: the 10 × 10 texels under it are left out, the stats are the rest by hand', () => {
    const lit = litFloor();
    // Centred at (1.5, 1.7): it covers x 1.0–2.0 (texel centres 1.05…1.95, i = 10…19), z 1.2–2.2 (j = 12…21).
    const box = { id: 'box', mesh: boxMesh(1, 0.5, 1), position: [1.5, 0, 1.7] as [number, number, number], yaw: 0, scale: 1 };
    const prepared = prepareObjects([box], { texelSize: 0.1 });
    expect(floorUnderObjects(lit.layouts.floor, prepared).reduce((a, b) => a + b, 0)).toBe(100);
    const hand = byHand((x, z) => Math.abs(x - 1.5) < 0.5 && Math.abs(z - 1.7) < 0.5);
    expect(hand.kept).toHaveLength(30 * 35 - 100);
    const s = floorStats(lit, prepared);
    expect(s.points).toBe(950);
    expect(s.avg).toBeCloseTo(hand.avg, 3);
    expect(s.min).toBeCloseTo(hand.min, 9);
    expect(s.max).toBeCloseTo(hand.max, 9);
    expect(s.u0).toBeCloseTo(hand.min / hand.avg, 6);
    // Without the objects every texel counts (the map itself is the same).
    expect(floorStats(lit).points).toBe(1050);
    expect(floorStats(lit).avg).toBeCloseTo(byHand(() => false).avg, 3);
  });

  it('a box turned 45°: the texels whose centres lie in the turned square; a box hung 1 m up hides nothing', () => {
    const lit = litFloor();
    const turned = { id: 'turned', mesh: boxMesh(1, 0.4, 1), position: [1.5, 0, 1.7] as [number, number, number], yaw: 45, scale: 1 };
    const hung = { id: 'hung', mesh: boxMesh(0.8, 0.3, 0.4), position: [0.6, 1, 0.6] as [number, number, number], yaw: 0, scale: 1 };
    const prepared = prepareObjects([turned, hung], { texelSize: 0.1 });
    // A unit square turned 45° about (1.5, 1.7): |dx| + |dz| ≤ √2 / 2 (a diamond).
    const hand = byHand((x, z) => Math.abs(x - 1.5) + Math.abs(z - 1.7) <= Math.SQRT1_2);
    const s = floorStats(lit, prepared);
    expect(s.points).toBe(hand.kept.length);
    expect(s.avg).toBeCloseTo(hand.avg, 3);
    expect(s.min).toBeCloseTo(hand.min, 9);
    expect(s.max).toBeCloseTo(hand.max, 9);
  });
});
