/**
 * The room-shape chunk (roomShapeSupport.ts): everything rooms of any shape add to the model —
 * the shape's rules and geometry (src/core/room), validate()'s rules for the shape and for what is
 * placed in it, the file schema of `room.shape`, the editor's actions; daylight through the
 * windows (its rules, file schema, actions and the lighting scene's sky, issue 30); and the configuration
 * file's steps from versions before 8 (legacyMigrations.ts), as rare as a shape on a first visit. Only loadRoomShapeSupport()
 * imports it in the browser (a lazy chunk); Node hosts and the tests import it directly.
 */
import { ceilingHeightAt } from '../../room/ceilingHeightAt';
import { roomShapeActionDefinitions } from './roomShapeActionDefinitions';
import { scaleRoomShape } from './scaleRoomShape';
import type { Room, RoomShape } from '../configuration/configuration';
import { shapedRoom } from '../configuration/roomShape';
import { readRoomShape } from '../files/roomShapeFileSchema';
import { legacyMigrations } from '../files/migrations/legacyMigrations';
import { configurationObjectMisfit } from '../objects/objectInShapedRoom';
import { roomShapeProblems } from '../validation/roomShapeProblems';
import { shapedSystemFit } from '../validation/shapedSystemFit';
import type { RoomShapeSupport } from '../configuration/roomShapeSupport';
import { configurationDaylightProblems } from '../validation/daylightProblems';
import { readDaylight } from '../files/daylightFileSchema';
import { lightingDaylight } from '../files/lightingDaylight';

const shaped = (room: Room) => {
  const found = shapedRoom(room);
  if (!found) throw new Error('shapedRoom: the room has no shape');
  return found;
};

export const roomShapeSupportChunk: RoomShapeSupport = {
  problems: (room) => roomShapeProblems(room as Room & { shape: RoomShape }),
  systemFit: shapedSystemFit,
  objectMisfit: configurationObjectMisfit,
  ceilingAt: (room, x, z) => ceilingHeightAt(shaped(room), x, z),
  shapedRoom: shaped,
  scale: scaleRoomShape,
  readShape: readRoomShape,
  actions: roomShapeActionDefinitions,
  daylightProblems: configurationDaylightProblems,
  readDaylight,
  lightingDaylight,
  legacyMigrations,
};
