/**
 * The inverse of normaliseRoom: the room as its author wrote it (corners, wall indices, offsets
 * and per-wall reflectances in the input's order and orientation), so a normalised room can be
 * written back as the version-3 `room` object it was read from (docs/scene-format.md).
 */
import type { Room, RoomRgb } from './normaliseRoom';
import type { PlanPoint } from './planPolygon';
import type { RoomInput, RoomOpening, RoomReflectance, RoomSlope } from './roomInput';

/** A reflectance as written: a grey number when its channels are equal, else [r, g, b]. */
export function compactReflectance(r: RoomRgb): RoomReflectance {
  return r[0] === r[1] && r[1] === r[2] ? r[0] : [r[0], r[1], r[2]];
}

/**
 * The input a normalised room came from: normaliseRoom(roomInputOf(room)) equals `room`. Wall
 * reflectances come back as one value when all walls share it, else one [r, g, b] per wall (never
 * three bare numbers, which would read as one colour).
 */
export function roomInputOf(room: Room): RoomInput {
  const n = room.corners.length;
  // Reversing is its own inverse: c0 stays first and the rest run backwards.
  const outline: PlanPoint[] = room.reversed ? [room.corners[0], ...room.corners.slice(1).reverse()] : [...room.corners];
  const byInput = [...room.walls].sort((a, b) => a.inputIndex - b.inputIndex);
  const wallRgb = byInput.map((w) => w.reflectance);
  const allSame = wallRgb.every((r) => r.every((v, c) => v === wallRgb[0][c]));
  const slopes: RoomSlope[] = [...room.slopes]
    .sort((a, b) => a.inputIndex - b.inputIndex)
    .map((s) => {
      const own = s.reflectance.some((v, c) => v !== room.ceilingReflectance[c]);
      return { wall: room.walls[s.wall].inputIndex, kneeHeight: s.kneeHeight, pitch: s.pitch, ...(own ? { reflectance: compactReflectance(s.reflectance) } : {}) };
    });
  const openings: RoomOpening[] = [...room.openings]
    .sort((a, b) => a.inputIndex - b.inputIndex)
    .map((o) => {
      const wall = room.walls[o.wall];
      // Measured back from the other end; rounded to the nanometre so the two subtractions' float noise does not reach a file.
      const offset = room.reversed ? Math.round((wall.length - o.offset - o.width) * 1e9) / 1e9 : o.offset;
      return { wall: wall.inputIndex, offset, width: o.width, sill: o.sill, height: o.height, kind: o.kind };
    });
  return {
    outline: n > 0 ? outline : [],
    height: room.height,
    ...(slopes.length > 0 ? { slopes } : {}),
    ...(openings.length > 0 ? { openings } : {}),
    reflectance: {
      floor: compactReflectance(room.floorReflectance),
      ceiling: compactReflectance(room.ceilingReflectance),
      walls: allSame ? compactReflectance(wallRgb[0]) : wallRgb.map((r): RoomReflectance => [r[0], r[1], r[2]]),
    },
  };
}
