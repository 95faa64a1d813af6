/**
 * The plan footprint follows the aim (docs/aiming.md): the tilted beam cone traced to the room's
 * surfaces (src/core/model/modules/coneOutline.ts), checked against the conic section by hand:
 * a cone of half angle α tilted t from nadir at height h lands on the floor between
 * h·tan(t − α) and h·tan(t + α) along the aim direction, and every hit lies exactly α from
 * the axis (the cone's defining property).
 */
import { describe, expect, it } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { aimAxis } from '../../../src/core/model/modules/aim';
import { coneRoomOutline } from '../../../src/core/model/modules/coneOutline';
import type { ModuleInstance } from '../../../src/core/model/configuration/configuration';
import type { ModulePlacement } from '../../../src/core/model/rails/geometry';
import type { Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { moduleFootprint } from '../../../src/ui/planner/moduleFootprint';

const DEG = Math.PI / 180;
const room = { width: 6, depth: 5, height: 3 };
const placement = (heading: number): ModulePlacement => ({
  moduleId: 'm1',
  railId: 'r1',
  systemId: 's1',
  offset: 0,
  length: 0.15,
  centre: [3, 2.5],
  heading,
  footprint: { centre: [3, 2.5], axis: [1, 0], halfLength: 0.075, halfWidth: 0.025 },
});
const spot = (aim?: ModuleInstance['aim']): ModuleInstance => ({ id: 'm1', type: 'spot', beam: 'medium', cct: 3000, dimming: 1, ...(aim ? { aim } : {}) });

const angle = (a: Vec3, b: Vec3) => Math.acos((a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (Math.hypot(...a) * Math.hypot(...b))) / DEG;

describe('coneRoomOutline', () => {
  it('straight down: a circle of radius h·tan α on the floor', () => {
    const hits = coneRoomOutline([3, 2.4, 2.5], [0, -1, 0], 15, room, 48);
    expect(hits).toHaveLength(48);
    for (const h of hits) {
      expect(h.surface).toBe('floor');
      expect(h.point[1]).toBe(0);
      expect(Math.hypot(h.point[0] - 3, h.point[2] - 2.5)).toBeCloseTo(2.4 * Math.tan(15 * DEG), 12);
    }
  });

  it('tilted: every hit lies α from the axis; the floor part spans h·tan(t − α)…h·tan(t + α) along the aim', () => {
    const apex: Vec3 = [1, 2.5, 2.5];
    const t = 40;
    const axis = aimAxis(0, { rotation: 0, tilt: t });
    const hits = coneRoomOutline(apex, axis, 15, room, 360);
    for (const h of hits) expect(angle([h.point[0] - apex[0], h.point[1] - apex[1], h.point[2] - apex[2]], axis)).toBeCloseTo(15, 6);
    const xs = hits.map((h) => h.point[0] - apex[0]);
    // In the aim plane (rays k = 0 and 180 of 360 lie there), the nearest and farthest floor hits.
    expect(Math.min(...xs)).toBeCloseTo(2.5 * Math.tan(25 * DEG), 9);
    expect(Math.max(...xs)).toBeCloseTo(2.5 * Math.tan(55 * DEG), 9);
  });

  it('past the horizon the cone reaches a wall, and the hits stay on the room surfaces', () => {
    const apex: Vec3 = [1, 2.5, 2.5];
    const hits = coneRoomOutline(apex, aimAxis(0, { rotation: 0, tilt: 80 }), 20, room, 90);
    const surfaces = new Set(hits.map((h) => h.surface));
    expect(surfaces.has('east')).toBe(true);
    expect(surfaces.has('floor')).toBe(true);
    for (const h of hits) {
      expect(h.point[0]).toBeGreaterThanOrEqual(0);
      expect(h.point[0]).toBeLessThanOrEqual(room.width);
      expect(h.point[1]).toBeGreaterThanOrEqual(0);
      expect(h.point[1]).toBeLessThanOrEqual(room.height);
      if (h.surface === 'east') expect(h.point[0]).toBe(room.width);
    }
  });
});

describe('moduleFootprint with an aim', () => {
  it('a tilted spot: the beam cone on the floor, toward heading + rotation', () => {
    // Rail along +x; rotation 90 turns the aim to plan direction (cos 90°, −sin 90°): −z, up on the plan.
    const f = moduleFootprint(placement(0), spot({ rotation: 90, tilt: 30 }), defaultCatalog, 2, null, room)!;
    expect(f.kind).toBe('polygon');
    if (f.kind !== 'polygon') return;
    const zs = f.points.map((p) => p.z);
    // The medium spot's catalog beam is 30°: α = 15°.
    expect(Math.max(...zs)).toBeCloseTo(2.5 - 2 * Math.tan(15 * DEG), 2);
    expect(Math.min(...zs)).toBeCloseTo(2.5 - 2 * Math.tan(45 * DEG), 2);
    const xs = f.points.map((p) => p.x);
    expect((Math.max(...xs) + Math.min(...xs)) / 2).toBeCloseTo(3, 9);
  });

  it('untilted, the rotation turns the ellipse only; no aim keeps the old ellipse', () => {
    const plain = moduleFootprint(placement(20), spot(), defaultCatalog, 2, null, room)!;
    const turned = moduleFootprint(placement(20), spot({ rotation: 30, tilt: 0 }), defaultCatalog, 2, null, room)!;
    if (plain.kind !== 'ellipse' || turned.kind !== 'ellipse') throw new Error('expected ellipses');
    expect(plain.ellipse.rotationDeg).toBe(-20);
    expect(turned.ellipse.rotationDeg).toBe(-50);
    expect(turned.ellipse.rx).toBeCloseTo(2 * Math.tan(15 * DEG), 12);
  });

  it('a tilted module needs the room to trace its cone', () => {
    expect(moduleFootprint(placement(0), spot({ rotation: 0, tilt: 30 }), defaultCatalog, 2, null)).toBeNull();
  });
});
