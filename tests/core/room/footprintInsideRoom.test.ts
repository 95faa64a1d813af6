import { describe, expect, it } from 'vitest';
import { footprintInsideOutline, lowestCeilingOver, solidFitsRoom } from '../../../src/core/room/footprintInsideRoom';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import type { PlanPoint } from '../../../src/core/room/planPolygon';
import { issueExample, L_OUTLINE } from './roomFixtures';

const rect = (x0: number, z0: number, x1: number, z1: number): PlanPoint[] => [
  [x0, z0],
  [x1, z0],
  [x1, z1],
  [x0, z1],
];

describe('footprints in a room of any shape', () => {
  it('inside the L, touching walls, across the notch, around the inner corner', () => {
    expect(footprintInsideOutline(L_OUTLINE, rect(1, 1, 2, 2))).toBe(true);
    expect(footprintInsideOutline(L_OUTLINE, rect(0, 0, 6, 0.05))).toBe(true); // along the north wall
    expect(footprintInsideOutline(L_OUTLINE, rect(4, 3.5, 5, 4))).toBe(false); // in the notch
    expect(footprintInsideOutline(L_OUTLINE, rect(3, 2.5, 4, 3.5))).toBe(false); // over the inner corner (3.5, 3)
    // A thin rail with both ends in the room, from the west wing's south end to the east wing:
    // it passes x = 3.5 at z ≈ 3.56, through the notch.
    expect(
      footprintInsideOutline(L_OUTLINE, [
        [1, 4.5],
        [5.5, 2.8],
        [5.507, 2.819],
        [1.007, 4.519],
      ]),
    ).toBe(false);
    // Turned to pass x = 3.5 at z ≈ 2.3, it stays in the room.
    expect(
      footprintInsideOutline(L_OUTLINE, [
        [1, 4.5],
        [5.5, 0.5],
        [5.515, 0.517],
        [1.015, 4.517],
      ]),
    ).toBe(true);
    // The same reversed outline gives the same answers.
    const reversed = [L_OUTLINE[0], ...L_OUTLINE.slice(1).reverse()];
    expect(footprintInsideOutline(reversed, rect(1, 1, 2, 2))).toBe(true);
    expect(footprintInsideOutline(reversed, rect(3, 2.5, 4, 3.5))).toBe(false);
  });

  it("the ceiling over a footprint under the issue's 40° slope, and solids that fit or reach through it", () => {
    const room = normaliseRoom(issueExample);
    const t = Math.tan((40 * Math.PI) / 180);
    // A 2 m × 0.2 m rail footprint running along z from 0.4 to 2.4 m: lowest at z = 0.4.
    const rail = rect(2, 0.4, 2.2, 2.4);
    expect(lowestCeilingOver(room, rail)).toBeCloseTo(1.2 + 0.4 * t, 12);
    expect(solidFitsRoom(room, rail, 1.2 + 0.4 * t - 0.01)).toBe(true);
    expect(solidFitsRoom(room, rail, 1.2 + 0.4 * t + 0.01)).toBe(false);
    // Far from the slope the flat ceiling holds.
    expect(lowestCeilingOver(room, rect(1, 4, 2, 4.5))).toBe(2.6);
  });
});
