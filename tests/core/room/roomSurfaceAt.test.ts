/** Which surface of a room of any shape a point lies on (probe points, issue 29), and the report's room geometry. */
import { describe, expect, it } from 'vitest';
import { normaliseRoom } from '../../../src/core/room/normaliseRoom';
import { roomSurfaceAt } from '../../../src/core/room/roomSurfaceAt';
import { shapedRoomReport } from '../../../src/hosts/node/bakeSummary';
import { issueExample } from './roomFixtures';

const room = normaliseRoom(issueExample);
const idAt = (p: [number, number, number]) => {
  const at = roomSurfaceAt(room, p, 0.01);
  return at.surface ? at.surface.id : at.opening ? `opening ${at.opening.index} of ${at.opening.surface.id}` : `none, nearest ${at.nearest?.surface.id ?? '-'}`;
};

describe('roomSurfaceAt', () => {
  it('finds the floor, the flat ceiling, the slope and each wall, as the author numbered them', () => {
    expect(idAt([1, 0, 1])).toBe('floor');
    expect(idAt([1, 0.005, 4.5])).toBe('floor');
    expect(idAt([1, 2.6, 4])).toBe('ceiling');
    // The slope on wall 0 (z = 0): 1.2 m + z·tan 40° up to the 2.6 m ceiling.
    const t = Math.tan((40 * Math.PI) / 180);
    expect(idAt([2, 1.2 + 0.5 * t, 0.5])).toBe('slope-0');
    expect(idAt([2, 1, 0])).toBe('wall-0');
    expect(idAt([6, 1, 1])).toBe('wall-1');
    expect(idAt([5, 1, 3])).toBe('wall-2');
    expect(idAt([3.5, 1, 4])).toBe('wall-3');
    expect(idAt([0, 1, 2])).toBe('wall-5');
  });

  it('says why a point is on no surface: in an opening, in the notch, or off every plane', () => {
    // The door in wall 4 (z = 5, running from x = 3.5 to 0): 0.8 to 1.7 m from its start, so x 1.8 to 2.7.
    expect(idAt([2.2, 1, 5])).toBe('opening 0 of wall-4');
    expect(idAt([1, 1, 5])).toBe('wall-4');
    // In the notch: the notch's wall 2 (z = 3) is the nearest plane whose polygon holds the point's projection.
    expect(idAt([5, 0, 4])).toBe('none, nearest wall-2');
    expect(idAt([1, 0.3, 1])).toBe('none, nearest floor');
    // Above the slope (in the attic, outside the room) but within the plan: the slope is the nearest plane there.
    expect(idAt([2, 2.5, 0.5])).toMatch(/^none, nearest /);
  });

  it("the report's room geometry: the floor polygon's area, each surface's area and its openings", () => {
    const r = shapedRoomReport(room);
    expect(r.floor_area).toBeCloseTo(6 * 5 - 2.5 * 2, 12);
    expect(r.surfaces.map((s) => s.id).sort()).toEqual(['ceiling', 'floor', 'slope-0', 'wall-0', 'wall-1', 'wall-2', 'wall-3', 'wall-4', 'wall-5']);
    expect(r.openings_area).toBeCloseTo(0.9 * 2, 12);
    const door = r.surfaces.find((s) => s.id === 'wall-4')!;
    // Wall 4 is 3.5 m long under the flat 2.6 m ceiling, less the 0.9 × 2 m door.
    expect(door.area).toBeCloseTo(3.5 * 2.6 - 1.8, 12);
    expect(door.openings_area).toBeCloseTo(1.8, 12);
  });
});
