import { describe, expect, it } from 'vitest';
import { roomProblems } from '../../../src/core/room/roomProblems';
import type { RoomInput } from '../../../src/core/room/roomInput';
import { attic, issueExample, L_OUTLINE, plainReflectance } from './roomFixtures';

const withOutline = (outline: [number, number][]): RoomInput => ({ outline, height: 2.5, reflectance: plainReflectance });
const first = (room: RoomInput) => {
  const problems = roomProblems(room);
  expect(problems.length).toBeGreaterThan(0);
  return problems[0];
};

describe('roomProblems', () => {
  it('accepts the issue example, in either orientation, and the box', () => {
    expect(roomProblems(issueExample)).toEqual([]);
    expect(roomProblems(attic)).toEqual([]);
    // Reversed: corner 0 kept, wall i becomes wall n − 1 − i (the door's wall 4 → 1, the slope's 0 → 5).
    const reversed: RoomInput = { ...issueExample, outline: [L_OUTLINE[0], ...L_OUTLINE.slice(1).reverse()], slopes: [{ wall: 5, kneeHeight: 1.2, pitch: 40 }], openings: [{ ...issueExample.openings![0], wall: 1 }] };
    expect(roomProblems(reversed)).toEqual([]);
  });

  it('names the outline problems with code, params and path', () => {
    expect(
      first(
        withOutline([
          [0, 0],
          [1, 0],
        ]),
      ),
    ).toMatchObject({ code: 'room-corner-count', params: { count: 2, min: 3, max: 64 } });
    expect(
      first(
        withOutline([
          [0, 0],
          [4, 0],
          [4, 0.05],
          [4, 3],
          [0, 3],
        ]),
      ),
    ).toMatchObject({
      code: 'room-wall-short',
      path: 'room.outline[1]',
      params: { wall: 1, length: 0.05, min: 0.1 },
      message: 'wall 1 (corner 1 to corner 2) is 0.05 m long; each wall must be at least 0.1 m',
    });
    // Corners 1 and 3 of this dart are 0.05 m apart though no wall is short.
    expect(
      first(
        withOutline([
          [0, 0],
          [3, 1],
          [0, 2],
          [3.05, 1],
          [4, 3],
          [-1, 3],
        ]),
      ),
    ).toMatchObject({ code: 'room-corners-close', params: { corner: 1, other: 3, distance: 0.05 } });
    // A bow tie: walls 0 and 2 cross.
    expect(
      first(
        withOutline([
          [0, 0],
          [2, 2],
          [2, 0],
          [0, 2],
        ]),
      ),
    ).toMatchObject({ code: 'room-self-intersection', params: { wall: 0, other: 2 } });
    // Wall 2 folds back along wall 1.
    expect(
      first(
        withOutline([
          [0, 0],
          [4, 0],
          [4, 3],
          [4, 1],
          [0, 3],
        ]),
      ),
    ).toMatchObject({ code: 'room-self-intersection', params: { wall: 1, other: 2 } });
    expect(
      first(
        withOutline([
          [0, 0],
          [4, 0],
          [4, Number.NaN],
        ]),
      ),
    ).toMatchObject({ code: 'room-corner-invalid', path: 'room.outline[2]' });
  });

  it('names the slope problems', () => {
    const slope = (s: object) => first({ ...attic, slopes: [s as never] });
    expect(slope({ wall: 4, kneeHeight: 1, pitch: 30 })).toMatchObject({ code: 'room-slope-wall', path: 'room.slopes[0].wall', params: { slope: 0, wall: '4', last: 3 } });
    expect(slope({ wall: 0, kneeHeight: 1, pitch: 90 })).toMatchObject({ code: 'room-slope-pitch', path: 'room.slopes[0].pitch' });
    expect(slope({ wall: 0, kneeHeight: 1, pitch: 0 })).toMatchObject({ code: 'room-slope-pitch' });
    expect(slope({ wall: 0, kneeHeight: 2.7, pitch: 30 })).toMatchObject({ code: 'room-slope-knee', params: { slope: 0, value: '2.7', height: 2.6 } });
    expect(
      first({
        ...attic,
        slopes: [
          { wall: 0, kneeHeight: 1, pitch: 30 },
          { wall: 0, kneeHeight: 1.5, pitch: 20 },
        ],
      }),
    ).toMatchObject({ code: 'room-slope-twice', params: { slope: 1, other: 0, wall: 0 } });
    // In the L, a steep slope on wall 2 ((6, 3) → (3.5, 3), facing north into the east wing) runs on beyond
    // its wall's line over the west wing: at corner 4 (3.5, 5) the plane is 0.5 − tan 60°·2 < 0.
    expect(first({ ...issueExample, slopes: [{ wall: 2, kneeHeight: 0.5, pitch: 60 }], openings: [] })).toMatchObject({ code: 'room-ceiling-below-floor', path: 'room.outline[4]', params: { corner: 4 } });
  });

  it('names the opening problems', () => {
    const opening = (o: object, room: RoomInput = attic) => first({ ...room, openings: [o as never] });
    const door = { wall: 1, offset: 1, width: 0.9, sill: 0, height: 2, kind: 'door' };
    expect(roomProblems({ ...attic, openings: [door as never] })).toEqual([]);
    expect(opening({ ...door, wall: 9 })).toMatchObject({ code: 'room-opening-wall', path: 'room.openings[0].wall' });
    expect(opening({ ...door, offset: 5.5 })).toMatchObject({ code: 'room-opening-beyond-wall', params: { opening: 0, wall: 1, end: 6.4, length: 6 } });
    expect(opening({ ...door, offset: -0.1 })).toMatchObject({ code: 'room-opening-beyond-wall' });
    expect(opening({ ...door, width: 0 })).toMatchObject({ code: 'room-opening-size', params: { dimension: 'width' } });
    expect(opening({ ...door, sill: -1 })).toMatchObject({ code: 'room-opening-sill' });
    expect(opening({ ...door, kind: 'hatch' })).toMatchObject({ code: 'room-opening-kind' });
    // Wall 0 carries the slope: its top is the knee, 1.2 m.
    expect(opening({ ...door, wall: 0 })).toMatchObject({ code: 'room-opening-above-ceiling', params: { opening: 0, wall: 0, top: 2, ceiling: 1.2 } });
    // Wall 1 (east, x = 4) under the slope: at u = 0.5 m the ceiling is 1.2 + tan 40°·0.5 = 1.62 m.
    expect(opening({ ...door, offset: 0.5, width: 0.5, sill: 0.5, height: 1.2 })).toMatchObject({ code: 'room-opening-above-ceiling', params: { top: 1.7, ceiling: 1.62 } });
    const window = { wall: 1, offset: 1.5, width: 1, sill: 1, height: 1, kind: 'window' };
    expect(first({ ...attic, openings: [door as never, window as never] })).toMatchObject({ code: 'room-openings-overlap', path: 'room.openings[1]', params: { opening: 1, other: 0, wall: 1 } });
    // Side by side (touching) is fine.
    expect(roomProblems({ ...attic, openings: [door as never, { ...window, offset: 1.9 } as never] })).toEqual([]);
  });

  it('names reflectance problems per wall', () => {
    expect(first({ ...attic, reflectance: { ...plainReflectance, walls: [0.5, 0.5, 0.5, 0.5, 0.5] } })).toMatchObject({ code: 'room-wall-reflectance-count', params: { count: 5, walls: 4 } });
    expect(first({ ...attic, reflectance: { ...plainReflectance, walls: [0.5, 0.5, 1, 0.5] } })).toMatchObject({ code: 'room-reflectance', path: 'room.reflectance.walls[2]' });
    expect(first({ ...attic, height: 0.05 })).toMatchObject({ code: 'room-height', params: { min: 0.1 } });
  });
});
