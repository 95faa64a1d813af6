/**
 * Rooms of any shape (and the steps from files older than version 8), loaded when a room first gets or arrives with a shape (issue 29; docs/architecture.md,
 * "The room-shape chunk"). The shape's rules, file schema, geometry and editing actions are ~10 kB
 * gzip that a shopper with a box room never needs, so the first screen holds only this hook:
 * validate(), the file reader, setRoom and the action registry ask the installed support when a
 * room has a `shape`, and every way a shape can come in (a saved or shared configuration, a file,
 * the embedding API, the room-shape button) awaits loadRoomShapeSupport() first. A shape met
 * before that is an error (RoomShapeSupportMissing), never a shape silently dropped or judged as a box.
 * The chunk is actions/roomShapeChunk.ts, fetched by loadRoomShapeSupport (actions/loadRoomShapeSupport.ts);
 * Node hosts and the tests install it statically (installRoomShapeSupport(roomShapeSupportChunk)).
 */
import { InputError, type CodedText } from '../../inputError';
import type { MeshPlacement } from '../../mesh/placeMesh';
import type { TriangleMesh } from '../../mesh/triangleMesh';
import type { Room as ShapedRoom } from '../../room/normaliseRoom';
import type { PlanPoint } from '../../room/planPolygon';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration, LightSystem, Room } from './configuration';
import type { Problem } from './problem';
import type { DaylightSettings } from './daylightSettings';
import type { LightingDaylight } from '../lightingScene/lightingScene';

/** An object's words as validate() names it: its name, id and library item. */
export type NamedObject = { name: string } & Record<string, string | number>;

/** One version step of the configuration file: a version-n document as version n + 1. */
export type MigrationStep = (doc: Record<string, unknown>, catalog: Catalog) => Record<string, unknown>;

export interface RoomShapeSupport {
  /** validate()'s rules of `room.shape` (room-*), at room.shape.* paths. */
  problems(room: Room): Problem[];
  /** A system that fits the box: its fit to the outline and under the slopes, or null. */
  systemFit(system: LightSystem, index: number, rects: readonly (readonly PlanPoint[])[], room: Room, catalog: Catalog): Problem | null;
  /** validate()'s sentence for a placed object outside the outline or above a slope; null when it fits or the shape breaks its own rules. */
  objectMisfit(room: Room, mesh: TriangleMesh, placement: MeshPlacement, named: NamedObject): { message: string; key: string; params: Record<string, string | number> } | null;
  /** The ceiling's height above a plan point of a room with a shape, metres. */
  ceilingAt(room: Room, x: number, z: number): number;
  /** The normalised room of a room with a shape (the lighting scene's version 3 room). */
  shapedRoom(room: Room): ShapedRoom;
  /** setRoom on a room with a shape: the outline scaled to the new size. */
  scale(state: Configuration, size: { width: number; depth: number; height: number }): Configuration;
  /** A configuration file's `room.shape` read: the shape, or the first problem as a coded sentence at its path under `prefix`. */
  readShape(value: unknown, prefix: readonly PropertyKey[]): { shape: Room['shape'] } | { problem: CodedText };
  /** The room-shape editor's action definitions by name (actions/roomShapeActionDefinitions.ts; typed there, this folder sits below actions). */
  actions: Readonly<Record<string, unknown>>;
  /** validate()'s rules of the daylight and the windows' glazing (daylight-*, window-glazing, glazing-not-window). */
  daylightProblems(config: Configuration): Problem[];
  /** A configuration file's `daylight` read (version 10), as readShape. */
  readDaylight(value: unknown, prefix: readonly PropertyKey[]): { daylight: DaylightSettings } | { problem: CodedText };
  /** The lighting scene's daylight of a configuration with a shape: the sky (none while off or at night) and each window's glazing; null when there is nothing to say. */
  lightingDaylight(config: Configuration): LightingDaylight | null;
  /** The configuration file's steps from versions before 8 (legacyMigrations.ts): rare files, kept off the first screen with the shape. */
  legacyMigrations: Record<number, MigrationStep>;
}

/** A room shape (or a room-shape action) met before the room-shape chunk was loaded: a bug in the caller, said plainly. */
export class RoomShapeSupportMissing extends InputError {
  override name = 'RoomShapeSupportMissing';
  constructor(what: string) {
    super(`${what}: this part of luxbox is still loading`, { code: 'roomShapeLoading' });
  }
}

let installed: RoomShapeSupport | null = null;

export function installRoomShapeSupport(support: RoomShapeSupport): void {
  installed = support;
}

/** The installed support, or null before the chunk has loaded. */
export function roomShapeSupport(): RoomShapeSupport | null {
  return installed;
}

/** The installed support; throws RoomShapeSupportMissing before the chunk has loaded. */
export function requireRoomShapeSupport(): RoomShapeSupport {
  if (!installed) throw new RoomShapeSupportMissing('room.shape');
  return installed;
}

/** Whether parsed scene-file JSON (any value) has daylight (version 10), which the chunk reads too. */
export function sceneDataHasDaylight(data: unknown): boolean {
  const c = typeof data === 'object' && data !== null ? (data as Record<string, unknown>).configuration : undefined;
  return typeof c === 'object' && c !== null && 'daylight' in c;
}

/** Whether parsed scene-file JSON (any value) has a room shape: `configuration.room.shape`. */
export function sceneDataHasRoomShape(data: unknown): boolean {
  const c = typeof data === 'object' && data !== null ? (data as Record<string, unknown>).configuration : undefined;
  const room = typeof c === 'object' && c !== null ? (c as Record<string, unknown>).room : undefined;
  return typeof room === 'object' && room !== null && 'shape' in room;
}

/**
 * Whether reading a scene file's text needs this chunk: a room shape, daylight, or a version before 8
 * (LEGACY_BELOW, whose steps are in the chunk). False for text that is not JSON: the reader then says what is wrong.
 */
export function sceneTextNeedsLazyModel(text: string | null | undefined): boolean {
  if (!text) return false;
  try {
    const data = JSON.parse(text) as { version?: unknown };
    return sceneDataHasRoomShape(data) || sceneDataHasDaylight(data) || (typeof data?.version === 'number' && data.version < 8);
  } catch {
    return false;
  }
}
