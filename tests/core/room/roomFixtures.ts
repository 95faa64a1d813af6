import type { RoomInput } from '../../../src/core/room/roomInput';

/** Issue 29's example outline: an L (6 × 5 m with a 2.5 × 2 m notch at x > 3.5, z > 3). */
export const L_OUTLINE: [number, number][] = [
  [0, 0],
  [6, 0],
  [6, 3],
  [3.5, 3],
  [3.5, 5],
  [0, 5],
];

export const plainReflectance = { floor: 0.25, ceiling: 0.8, walls: 0.5 };

/** Issue 29's example room: the L with a slope on wall 0 and a door in wall 4. */
export const issueExample: RoomInput = {
  outline: L_OUTLINE,
  height: 2.6,
  slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40 }],
  reflectance: plainReflectance,
  openings: [{ wall: 4, offset: 0.8, width: 0.9, sill: 0, height: 2.0, kind: 'door' }],
};

/** A 4 × 6 m attic room (x × z), flat ceiling 2.6 m, a slope on the north wall (knee 1.2 m, 40°). */
export const attic: RoomInput = {
  outline: [
    [0, 0],
    [4, 0],
    [4, 6],
    [0, 6],
  ],
  height: 2.6,
  slopes: [{ wall: 0, kneeHeight: 1.2, pitch: 40 }],
  reflectance: plainReflectance,
};

/** A gable: 5 × 4 m, slopes on north and south (knee 1 m, 45°) meeting at z = 2, 3 m up, under a 5 m flat ceiling they never reach. */
export const gable: RoomInput = {
  outline: [
    [0, 0],
    [5, 0],
    [5, 4],
    [0, 4],
  ],
  height: 5,
  slopes: [
    { wall: 0, kneeHeight: 1, pitch: 45 },
    { wall: 2, kneeHeight: 1, pitch: 45 },
  ],
  reflectance: plainReflectance,
};

/** A U (open to the south): 6 × 4 m with a 2 × 2.5 m bay cut from the middle of the south side. */
export const U_OUTLINE: [number, number][] = [
  [0, 0],
  [6, 0],
  [6, 4],
  [4, 4],
  [4, 1.5],
  [2, 1.5],
  [2, 4],
  [0, 4],
];
