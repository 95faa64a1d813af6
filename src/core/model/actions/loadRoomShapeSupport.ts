/**
 * Fetches the room-shape chunk (roomShapeChunk.ts) and installs it (configuration/roomShapeSupport.ts),
 * once: later calls share the same promise; a failed fetch may be tried again. In the browser build
 * this dynamic import is the chunk's only way in.
 */
import { installRoomShapeSupport, roomShapeSupport, type RoomShapeSupport } from '../configuration/roomShapeSupport';

let loading: Promise<RoomShapeSupport> | null = null;

export function loadRoomShapeSupport(): Promise<RoomShapeSupport> {
  const installed = roomShapeSupport();
  if (installed) return Promise.resolve(installed);
  loading ??= import('./roomShapeChunk').then(
    (m) => {
      installRoomShapeSupport(m.roomShapeSupportChunk);
      return m.roomShapeSupportChunk;
    },
    (e: unknown) => {
      loading = null;
      throw e;
    },
  );
  return loading;
}
