/**
 * Random rooms (star-shaped outlines of 3–12 corners in either orientation, 0–3 slopes, half of
 * them meeting the flat ceiling exactly over a corner, 0–2 openings; seeded): the surfaces close
 * the room (Σ A·n_out = 0), the ceiling parts cover the floor exactly once in plan, every corner
 * of every surface lies in the room, and the volume by the divergence theorem equals ∫ ceiling
 * height over the floor, integrated row by row in plan independently of the surfaces.
 */
import { describe, expect, it } from 'vitest';
import { ceilingHeightAt, pointInsideRoom } from '../../../src/core/room/ceilingHeightAt';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import { doubleSignedArea, type PlanPoint } from '../../../src/core/room/planPolygon';
import type { RoomInput, RoomOpening, RoomSlope } from '../../../src/core/room/roomInput';
import { roomProblems } from '../../../src/core/room/roomProblems';
import { roomSurfaces } from '../../../src/core/room/roomSurfaces';
import { createRng } from '../../fuzz/mutate';

function randomRoom(rng: ReturnType<typeof createRng>): RoomInput {
  const n = 3 + rng.int(10);
  const angles = Array.from({ length: n }, () => rng.next() * 2 * Math.PI).sort((a, b) => a - b);
  let outline: PlanPoint[] = angles.map((a) => {
    const r = 1.5 + 2.5 * rng.next();
    return [Math.round((3 + r * Math.cos(a)) * 1000) / 1000, Math.round((3 + r * Math.sin(a)) * 1000) / 1000];
  });
  if (rng.chance(0.5)) outline = outline.reverse();
  const height = 2.2 + rng.next();
  const slopes: RoomSlope[] = [];
  const walls = new Set<number>();
  for (let k = rng.int(4); k > 0; k--) {
    const wall = rng.int(n);
    if (walls.has(wall)) continue;
    walls.add(wall);
    const kneeHeight = 0.3 + rng.next() * (height - 0.3);
    let pitch = 15 + 45 * rng.next();
    if (rng.chance(0.5)) {
      // Degenerate on purpose: the slope meets the flat ceiling exactly over another corner.
      const [a, b] = [outline[wall], outline[(wall + 1) % n]];
      const c = outline[rng.int(n)];
      const len = Math.hypot(b[0] - a[0], b[1] - a[1]);
      const d = Math.abs(((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / len);
      if (d > 0.2 && height - kneeHeight > 0.05) pitch = (Math.atan((height - kneeHeight) / d) * 180) / Math.PI;
    }
    slopes.push({ wall, kneeHeight, pitch });
  }
  const openings: RoomOpening[] = [];
  for (let k = rng.int(3); k > 0; k--) {
    openings.push({ wall: rng.int(n), offset: 0.05 + rng.next() * 0.5, width: 0.3 + rng.next() * 0.6, sill: rng.next() * 0.5, height: 0.3 + rng.next() * 0.5, kind: rng.pick(['door', 'window', 'opening'] as const) });
  }
  return { outline, height, slopes, openings, reflectance: { floor: 0.2, ceiling: 0.7, walls: 0.5 } };
}

describe('random rooms', () => {
  it('close, cover the floor once under the ceiling, and hold the volume under the ceiling', () => {
    const rng = createRng(2929);
    let checked = 0;
    let withSlopes = 0;
    let withOpenings = 0;
    let nonConvexWithSlopes = 0;
    let reversed = 0;
    let maxVolumeError = 0;
    for (let attempt = 0; attempt < 600 && checked < 60; attempt++) {
      const input = randomRoom(rng);
      if (roomProblems(input).length > 0) continue;
      checked++;
      const room = normaliseRoom(input);
      const surfaces = roomSurfaces(room);
      if (room.slopes.length > 0) withSlopes++;
      if (room.openings.length > 0) withOpenings++;
      if (!room.convex && room.slopes.length > 0) nonConvexWithSlopes++;
      if (room.reversed) reversed++;
      const floorArea = Math.abs(doubleSignedArea(input.outline)) / 2;
      const sum = [0, 0, 0];
      let volume = 0;
      let ceilingPlan = 0;
      for (const s of surfaces) {
        const gross = s.area + s.openings.reduce((a, o) => a + o.area, 0);
        for (let k = 0; k < 3; k++) sum[k] += gross * s.outward[k];
        const p = s.polygons[0][0];
        volume += (gross * (s.outward[0] * p[0] + s.outward[1] * p[1] + s.outward[2] * p[2])) / 3;
        if (s.kind === 'ceiling' || s.kind === 'slope') ceilingPlan += s.area * -s.inward[1];
        for (const q of s.polygons.flat()) expect(pointInsideRoom(room, q, 1e-7)).toBe(true);
      }
      for (const v of sum) expect(Math.abs(v)).toBeLessThan(1e-9);
      expect(ceilingPlan).toBeCloseTo(floorArea, 9);
      // ∫ h over the floor, row by row: each row's exact stretches inside the outline (its edge
      // crossings), h integrated along each stretch by the midpoint rule (h is continuous there).
      const zs = input.outline.map((c) => c[1]);
      const [z0, z1] = [Math.min(...zs), Math.max(...zs)];
      const rows = 800;
      let integral = 0;
      for (let j = 0; j < rows; j++) {
        const z = z0 + ((j + 0.5) * (z1 - z0)) / rows;
        const cuts: number[] = [];
        input.outline.forEach((a, k) => {
          const b = input.outline[(k + 1) % input.outline.length];
          if (a[1] > z !== b[1] > z) cuts.push(a[0] + ((z - a[1]) * (b[0] - a[0])) / (b[1] - a[1]));
        });
        cuts.sort((a, b) => a - b);
        for (let k = 0; k + 1 < cuts.length; k += 2) {
          const steps = 64;
          const dx = (cuts[k + 1] - cuts[k]) / steps;
          for (let i = 0; i < steps; i++) integral += ceilingHeightAt(room, cuts[k] + (i + 0.5) * dx, z) * dx;
        }
      }
      integral *= (z1 - z0) / rows;
      maxVolumeError = Math.max(maxVolumeError, Math.abs(volume - integral) / volume);
    }
    // The generator must reach the interesting cases, or the test proves little.
    expect(checked).toBe(60);
    expect(withSlopes).toBeGreaterThan(10);
    expect(withOpenings).toBeGreaterThan(5);
    expect(nonConvexWithSlopes).toBeGreaterThan(5);
    expect(reversed).toBeGreaterThan(10);
    // The row integral's own error: measured 3e-5 at most (a sliver of a triangle).
    expect(maxVolumeError).toBeLessThan(1e-4);
  });
});
