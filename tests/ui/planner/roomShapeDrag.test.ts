import { describe, expect, it } from 'vitest';
import { slideOpening, snapCorner } from '../../../src/ui/planner/roomShapeDrag';
import type { PlanPoint } from '../../../src/core/room/planPolygon';

const L: PlanPoint[] = [
  [0, 0],
  [6, 0],
  [6, 3],
  [3.6, 3],
  [3.6, 5],
  [0, 5],
];

describe('room-shape drags', () => {
  it('a dragged corner lines up with its neighbours within 10 px, else lands on the 5 cm grid', () => {
    // 100 px per metre: 0.08 m off corner 2's z (8 px) lines up; 0.3 m off corner 4's x (30 px) goes to the grid.
    expect(snapCorner(L, 3, [3.33, 3.08], 100)).toEqual([3.35, 3]);
    // Zoomed out to 20 px per metre the same 0.3 m is 6 px: it lines up with corner 4's x.
    expect(snapCorner(L, 3, [3.3, 3.08], 20)).toEqual([3.6, 3]);
    expect(snapCorner(L, 0, [-0.52, 0.07], 100)).toEqual([-0.5, 0]);
  });

  it('a slid opening stays between the wall ends, on a centimetre', () => {
    expect(slideOpening(-0.4, 0.9, 6)).toBe(0);
    expect(slideOpening(5.5, 0.9, 6)).toBe(5.1);
    expect(slideOpening(2.345, 0.9, 6)).toBe(2.35);
  });
});
