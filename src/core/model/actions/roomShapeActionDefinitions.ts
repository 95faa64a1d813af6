/**
 * The room-shape editor's actions (roomShapeActions.ts) as one table, in the order the registry
 * lists them (roomShapeActionNames.ts). Part of the room-shape chunk (actions/roomShapeChunk.ts):
 * the registry finds them there once the chunk is installed.
 */
import {
  addRoomOpening,
  moveRoomCorner,
  removeRoomCorner,
  removeRoomOpening,
  removeRoomSlope,
  setRoomCornerAngle,
  setRoomOpening,
  setRoomShapePreset,
  setRoomSlope,
  setRoomWallLength,
  setWallFinish,
  splitRoomWall,
} from './roomShapeActions';
import { setDaylight, setWindowGlazing } from './daylightActions';

export const roomShapeActionDefinitions = {
  setRoomShapePreset,
  moveRoomCorner,
  splitRoomWall,
  setRoomWallLength,
  setRoomCornerAngle,
  removeRoomCorner,
  setRoomSlope,
  removeRoomSlope,
  addRoomOpening,
  setRoomOpening,
  removeRoomOpening,
  setWallFinish,
  setDaylight,
  setWindowGlazing,
} as const;
