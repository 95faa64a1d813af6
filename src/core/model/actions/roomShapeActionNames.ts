/**
 * The room-shape actions' names, on the first screen: the registry knows and types them
 * (actionDefinitions.ts) while their definitions stay in the room-shape chunk
 * (roomShapeActionDefinitions.ts, loaded by configuration/roomShapeSupport.ts). `import type` keeps
 * the chunk out of the first screen's bundle.
 */
import type { roomShapeActionDefinitions } from './roomShapeActionDefinitions';

export type RoomShapeActionDefinitions = typeof roomShapeActionDefinitions;
export type RoomShapeActionName = keyof RoomShapeActionDefinitions;

/** Each room-shape action's label (what listActions says before and after the chunk loads; the definitions take theirs from here). */
export const ROOM_SHAPE_ACTION_LABELS: Record<RoomShapeActionName, string> = {
  setRoomShapePreset: 'Room shape',
  moveRoomCorner: 'Move corner',
  splitRoomWall: 'Split wall',
  setRoomWallLength: 'Wall length',
  setRoomCornerAngle: 'Corner angle',
  removeRoomCorner: 'Remove corner',
  setRoomSlope: 'Slope',
  removeRoomSlope: 'Remove slope',
  addRoomOpening: 'Add opening',
  setRoomOpening: 'Opening',
  removeRoomOpening: 'Remove opening',
  setWallFinish: 'Wall finish',
  setDaylight: 'Daylight',
  setWindowGlazing: 'Window glazing',
};

/** In the registry's order (docs/embedding.md's action table); a Record above, so none can be missing. */
export const ROOM_SHAPE_ACTION_NAMES = Object.keys(ROOM_SHAPE_ACTION_LABELS) as RoomShapeActionName[];

export function isRoomShapeActionName(name: string): name is RoomShapeActionName {
  return (ROOM_SHAPE_ACTION_NAMES as readonly string[]).includes(name);
}
