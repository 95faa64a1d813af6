// Every Vitest file starts with the room-shape chunk installed, as the CLI does at start and the
// browser does before any shape can arrive (src/core/model/configuration/roomShapeSupport.ts).
// tests/core/model/roomShape/roomShapeSupport.test.ts checks the not-yet-loaded state on a fresh module.
import { installRoomShapeSupport } from '../../src/core/model/configuration/roomShapeSupport';
import { roomShapeSupportChunk } from '../../src/core/model/actions/roomShapeChunk';

installRoomShapeSupport(roomShapeSupportChunk);
