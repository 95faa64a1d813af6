/**
 * Today's box room (lighting scene versions 1 and 2) as a room of any shape: the rectangle
 * outline [0, 0] → [W, 0] → [W, D] → [0, D], so wall 0 is the north wall (z = 0), 1 the east
 * (x = W), 2 the south (z = D) and 3 the west (x = 0), as issue 29's contract says; the box's
 * faces and names are docs/scene-format.md "Units and frames".
 */
import type { RoomInput, RoomReflectance } from './roomInput';

/** The box's wall names in outline order. */
export const BOX_WALL_NAMES = ['north', 'east', 'south', 'west'] as const;
export type BoxWallName = (typeof BOX_WALL_NAMES)[number];

export interface BoxRoom {
  width: number;
  height: number;
  depth: number;
  reflectance: Record<'floor' | 'ceiling' | BoxWallName, RoomReflectance>;
}

/** A version-1/2 room as the version-3 room that means the same. */
export function boxRoomInput(box: BoxRoom): RoomInput {
  const { width: W, depth: D, reflectance: r } = box;
  return {
    outline: [
      [0, 0],
      [W, 0],
      [W, D],
      [0, D],
    ],
    height: box.height,
    reflectance: { floor: r.floor, ceiling: r.ceiling, walls: BOX_WALL_NAMES.map((name) => r[name]) },
  };
}
