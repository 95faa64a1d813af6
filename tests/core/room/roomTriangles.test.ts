import { describe, expect, it } from 'vitest';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import { pointInPolygon, type PlanPoint } from '../../../src/core/room/planPolygon';
import { roomProblems } from '../../../src/core/room/roomProblems';
import { earClip, roomTriangles, type RoomTriangles } from '../../../src/core/room/roomTriangles';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { createRng } from '../../fuzz/mutate';
import { gable, issueExample, U_OUTLINE } from './roomFixtures';

/** Per surface: Σ triangle area, and whether every triangle's right-hand normal points into the room. */
function check(mesh: RoomTriangles): void {
  const area = mesh.surfaces.map(() => 0);
  for (let t = 0; t < mesh.surfaceOf.length; t++) {
    const p = mesh.positions.slice(9 * t, 9 * t + 9);
    const e1 = [p[3] - p[0], p[4] - p[1], p[5] - p[2]];
    const e2 = [p[6] - p[0], p[7] - p[1], p[8] - p[2]];
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const s = mesh.surfaces[mesh.surfaceOf[t]];
    const len = Math.hypot(n[0], n[1], n[2]);
    expect((n[0] * s.inward[0] + n[1] * s.inward[1] + n[2] * s.inward[2]) / len).toBeCloseTo(1, 9);
    area[mesh.surfaceOf[t]] += len / 2;
  }
  mesh.surfaces.forEach((s, k) => expect(area[k], s.id).toBeCloseTo(s.area, 9));
}

describe('room triangles', () => {
  it('the issue room: every surface covered once, wound toward the inside, the door left open', () => {
    const mesh = roomTriangles(normaliseRoom(issueExample));
    check(mesh);
    // No triangle of wall 4 covers the door's middle (x 2.25, y 1, z 5).
    const wall = mesh.surfaces.findIndex((s) => s.id === 'wall-4');
    for (let t = 0; t < mesh.surfaceOf.length; t++) {
      if (mesh.surfaceOf[t] !== wall) continue;
      const p = mesh.positions.slice(9 * t, 9 * t + 9);
      const tri: PlanPoint[] = [
        [p[0], p[1]],
        [p[3], p[4]],
        [p[6], p[7]],
      ];
      expect(pointInPolygon([2.25, 1], tri, 0)).toBe(false);
    }
  });

  it('a gable with a window under a slope, and a U under a slope (two flat pieces)', () => {
    check(roomTriangles(normaliseRoom({ ...gable, openings: [{ wall: 1, offset: 1.5, width: 1, sill: 1, height: 1.5, kind: 'window' }] })));
    check(roomTriangles(normaliseRoom({ outline: U_OUTLINE, height: 2.5, slopes: [{ wall: 0, kneeHeight: 1, pitch: 45 }], reflectance: { floor: 0.2, ceiling: 0.8, walls: 0.5 } })));
  });

  it('ear clipping: random star-shaped polygons of either winding, areas exact', () => {
    const rng = createRng(77);
    let tested = 0;
    for (let r = 0; r < 400 && tested < 200; r++) {
      const n = 3 + rng.int(30);
      const angles = Array.from({ length: n }, () => rng.next() * 2 * Math.PI).sort((a, b) => a - b);
      // Star-shaped about the origin (so simple) only when no angular gap reaches π.
      if (angles.some((a, i) => (i + 1 < n ? angles[i + 1] : angles[0] + 2 * Math.PI) - a >= Math.PI)) continue;
      let poly: PlanPoint[] = angles.map((a) => {
        const radius = 0.5 + 3 * rng.next();
        return [radius * Math.cos(a), radius * Math.sin(a)];
      });
      if (rng.chance(0.5)) poly = poly.reverse();
      let shoelace = 0;
      for (let i = 0; i < n; i++) shoelace += poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1];
      const tris = earClip(poly);
      expect(tris).toHaveLength(n - 2);
      let sum = 0;
      for (const [a, b, c] of tris) {
        const twice = (poly[b][0] - poly[a][0]) * (poly[c][1] - poly[a][1]) - (poly[b][1] - poly[a][1]) * (poly[c][0] - poly[a][0]);
        expect(Math.sign(twice)).toBe(Math.sign(shoelace)); // the polygon's own winding
        sum += twice;
      }
      expect(sum).toBeCloseTo(shoelace, 9);
      tested++;
    }
    expect(tested).toBe(200);
  });

  it('random rooms with slopes and openings: every surface covered once', () => {
    const rng = createRng(4141);
    let checked = 0;
    for (let attempt = 0; attempt < 600 && checked < 40; attempt++) {
      const n = 3 + rng.int(10);
      const angles = Array.from({ length: n }, () => rng.next() * 2 * Math.PI).sort((a, b) => a - b);
      const outline: PlanPoint[] = angles.map((a) => [3 + (1.5 + 2.5 * rng.next()) * Math.cos(a), 3 + (1.5 + 2.5 * rng.next()) * Math.sin(a)]);
      const input: RoomInput = {
        outline,
        height: 2.5,
        slopes: rng.chance(0.7) ? [{ wall: rng.int(n), kneeHeight: 0.5 + rng.next(), pitch: 20 + 40 * rng.next() }] : [],
        openings: [{ wall: rng.int(n), offset: 0.1, width: 0.5, sill: 0.2, height: 0.4, kind: 'window' }],
        reflectance: { floor: 0.2, ceiling: 0.8, walls: 0.5 },
      };
      if (roomProblems(input).length > 0) continue;
      checked++;
      check(roomTriangles(normaliseRoom(input)));
    }
    expect(checked).toBe(40);
  });
});
