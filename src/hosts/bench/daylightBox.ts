import type { RoomInput, RoomOpening } from '../../core/room/roomInput';

/** The daylight box's window: 1.5 × 1.4 m in the south wall (z = 4), from x = 1.75 to 3.25 m, sill 0.9 m. */
export const DAYLIGHT_BOX_WINDOW: RoomOpening = { wall: 2, offset: 1.75, width: 1.5, sill: 0.9, height: 1.4, kind: 'window' };

/** The finishes of the daylight box unless a case says otherwise. */
export const DAYLIGHT_BOX_FINISHES = { floor: 0.3, ceiling: 0.8, walls: 0.5 };

/**
 * The room of the daylight bench and of the daylight tests (baker, reference, relight bases,
 * window panes, probe, CLI): 5 × 4 m, 2.8 m high, one south window (DAYLIGHT_BOX_WINDOW).
 */
export function daylightBox(reflectance: RoomInput['reflectance'] = DAYLIGHT_BOX_FINISHES): RoomInput {
  return {
    outline: [
      [0, 0],
      [5, 0],
      [5, 4],
      [0, 4],
    ],
    height: 2.8,
    openings: [DAYLIGHT_BOX_WINDOW],
    reflectance,
  };
}

/**
 * The daylight L of the bench and the tests (baker, reference, plan overlay): 6 × 6 m with a 3 × 3 m
 * notch, 2.6 m high; the west wing's south wall (wall 4, from (3, 6) to (0, 6)) has a 2 × 1.8 m window
 * at sill 0.5 m, partly hidden from the east wing by the inner corner.
 */
export function daylightL(reflectance: RoomInput['reflectance'] = DAYLIGHT_BOX_FINISHES): RoomInput {
  return {
    outline: [
      [0, 0],
      [6, 0],
      [6, 3],
      [3, 3],
      [3, 6],
      [0, 6],
    ],
    height: 2.6,
    openings: [{ wall: 4, offset: 0.5, width: 2, sill: 0.5, height: 1.8, kind: 'window' }],
    reflectance,
  };
}
