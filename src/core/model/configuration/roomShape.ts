/**
 * A configuration's room of any shape (Room.shape, docs/model.md "Room shape") as the geometry of
 * src/core/room sees it: each wall's finish, the room input, and the normalised room (worked out
 * once per shape object, since validate() asks after every action).
 */
import { inwardNormal } from '../../room/ceilingPlanes';
import { normaliseRoom, type Room as ShapedRoom } from '../../room/normaliseRoom';
import { doubleSignedArea } from '../../room/planPolygon';
import type { RoomInput } from '../../room/roomInput';
import { roomProblems as shapeRoomProblems, type RoomProblem } from '../../room/roomProblems';
import type { Reflectance } from '../lightingScene/lightingScene';
import { nearestBoxWall } from '../lightingScene/boxWallFacing';
import { reflectanceRgb } from '../lightingScene/reflectance';
import type { Room, RoomShape } from './configuration';

/**
 * Each wall's finish, in outline order: its own (shape.wallReflectance[i]) or, where the shape
 * gives none, the box wall's (north, east, south, west) whose inward normal is nearest the wall's
 * own, so a rectangle outline keeps the box's four finishes.
 */
export function wallFinishes(room: Pick<Room, 'reflectance'> & { shape: RoomShape }): Reflectance[] {
  const { outline, wallReflectance } = room.shape;
  const orientation: 1 | -1 = doubleSignedArea(outline) >= 0 ? 1 : -1;
  return outline.map((a, i) => wallReflectance?.[i] ?? room.reflectance[nearestBoxWall(inwardNormal(a, outline[(i + 1) % outline.length], orientation))]);
}

/** The shape as the room model's input: the configuration's height, floor and ceiling finishes, one [r, g, b] per wall (never three bare numbers, which read as one colour). */
export function shapeRoomInput(room: Room & { shape: RoomShape }): RoomInput {
  const { outline, slopes, openings } = room.shape;
  return {
    outline,
    height: room.height,
    slopes,
    openings,
    reflectance: { floor: room.reflectance.floor, ceiling: room.reflectance.ceiling, walls: wallFinishes(room).map((r) => reflectanceRgb(r)) },
  };
}

/** The shape's rules (src/core/room/roomProblems.ts), once per room object. */
const problemsOf = new WeakMap<Room, readonly RoomProblem[]>();
export function shapeProblems(room: Room & { shape: RoomShape }): readonly RoomProblem[] {
  let found = problemsOf.get(room);
  if (!found) problemsOf.set(room, (found = shapeRoomProblems(shapeRoomInput(room))));
  return found;
}

const normalised = new WeakMap<Room, ShapedRoom>();
/** The normalised room of a configuration room with a valid shape (shapeProblems empty); null for a box. Cached per room object. */
export function shapedRoom(room: Room): ShapedRoom | null {
  if (!room.shape) return null;
  let found = normalised.get(room);
  if (!found) normalised.set(room, (found = normaliseRoom(shapeRoomInput(room as Room & { shape: RoomShape }))));
  return found;
}
