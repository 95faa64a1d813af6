/**
 * Between a room of any shape and today's box (issue 29): which box wall (north, east, south,
 * west; docs/scene-format.md "Units and frames") a wall of any direction stands for, by its
 * inward normal. A configuration's walls without their own finish take the box wall's, and a
 * version-3 lighting scene fills the box record of reflectances (for readers that only know the
 * box) from the walls that face each way.
 */
import type { Room as ShapedRoom } from '../../room/normaliseRoom';
import { compactReflectance } from '../../room/roomInputOf';
import type { Reflectance, SurfaceName } from './lightingScene';

export const BOX_WALLS = ['north', 'east', 'south', 'west'] as const;
export type BoxWall = (typeof BOX_WALLS)[number];

/** Each box wall's inward normal in plan [x, z]: the north wall (z = 0) faces +z, the east wall (x = width) −x. */
export const BOX_WALL_INWARD: Record<BoxWall, readonly [number, number]> = {
  north: [0, 1],
  east: [-1, 0],
  south: [0, -1],
  west: [1, 0],
};

const dot = (a: readonly [number, number], b: readonly [number, number]): number => a[0] * b[0] + a[1] * b[1];

/** The box wall whose inward normal is nearest `inward` (largest dot product; a tie, at 45°, goes to the earlier of north, east, south, west). */
export function nearestBoxWall(inward: readonly [number, number]): BoxWall {
  let best: BoxWall = 'north';
  let bestDot = -Infinity;
  for (const name of BOX_WALLS) {
    const d = dot(inward, BOX_WALL_INWARD[name]);
    // 1e-12: a wall at exactly 45° must not flip with float noise.
    if (d > bestDot + 1e-12) [best, bestDot] = [name, d];
  }
  return best;
}

/**
 * The box record of reflectances for a room of any shape: floor and flat ceiling as they are, and
 * for each box wall the finish of the room's wall that faces most nearly its way (the largest dot
 * product of inward normals; among equals the longest wall, then the lowest index as written).
 */
export function boxReflectanceOf(room: ShapedRoom): Record<SurfaceName, Reflectance> {
  const facing = (name: BoxWall): Reflectance => {
    let best = room.walls[0];
    let bestDot = -Infinity;
    for (const w of room.walls) {
      const d = dot(w.inward, BOX_WALL_INWARD[name]);
      const better = d > bestDot + 1e-12 || (Math.abs(d - bestDot) <= 1e-12 && (w.length > best.length + 1e-12 || (Math.abs(w.length - best.length) <= 1e-12 && w.inputIndex < best.inputIndex)));
      if (better) [best, bestDot] = [w, d];
    }
    return compactReflectance(best.reflectance) as Reflectance;
  };
  return {
    floor: compactReflectance(room.floorReflectance) as Reflectance,
    ceiling: compactReflectance(room.ceilingReflectance) as Reflectance,
    north: facing('north'),
    south: facing('south'),
    west: facing('west'),
    east: facing('east'),
  };
}
