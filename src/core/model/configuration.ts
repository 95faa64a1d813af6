/**
 * The configuration: everything the user builds, as plain immutable data.
 * Positions of modules along rails are not stored: they follow from the rail's
 * distribution (src/core/model/distribution.ts), so a configuration cannot hold
 * overlapping modules by construction of its layout rule.
 */
import type { Distribution } from './catalogSchema';
import type { DmxPatch } from './dmxPatch';
import type { Reflectance, SurfaceName } from './lightingScene';

export type { Distribution };

export interface Room {
  /** x extent, metres */
  width: number;
  /** z extent, metres */
  depth: number;
  /** y extent (floor to ceiling), metres */
  height: number;
  /** Surface reflectances handed to the baker. */
  reflectance: Record<SurfaceName, Reflectance>;
}

export interface ModuleInstance {
  readonly id: string;
  /** Catalog module type id. */
  readonly type: string;
  /** Beam (optic variant) id of that type. */
  readonly beam: string;
  /** Colour temperature, kelvin; one of the type's ccts. */
  readonly cct: number;
  /** 0..1 multiplier on intensity. */
  readonly dimming: number;
  /** Where a lighting console drives it (docs/live-control.md); absent: not patched. Scene file version 2. */
  readonly dmx?: DmxPatch;
}

export interface Rail {
  readonly id: string;
  /** Metres, on the catalog's step grid. */
  readonly length: number;
  readonly distribution: Distribution;
  /** In order from the rail's start to its end. */
  readonly modules: readonly ModuleInstance[];
}

/** How rail i is joined to rail i+1. */
export interface Joint {
  /** Catalog connector id. */
  readonly connector: string;
  /** Degrees, counterclockwise seen from above positive (a left turn); ±angle of the connector, 0 for straight. */
  readonly turn: number;
}

export interface LightSystem {
  readonly id: string;
  /** Preset it was placed from (informational). */
  readonly presetId?: string;
  /** World x, z of the start of the first rail (the system's anchor), metres. */
  readonly x: number;
  readonly z: number;
  /** Heading of the first rail, degrees in [0, 360), counterclockwise seen from above; 0 = along +x. */
  readonly rotation: number;
  /** Ceiling to photometric centre of the modules, metres. */
  readonly suspension: number;
  readonly rails: readonly Rail[];
  /** joints[i] joins rails[i] to rails[i+1]; length rails.length − 1. */
  readonly joints: readonly Joint[];
}

export interface Configuration {
  readonly room: Room;
  readonly systems: readonly LightSystem[];
  /** Next number for generated ids ('s7', 'r8', 'm9'); keeps ids unique and deterministic. */
  readonly nextId: number;
}

/** Room limits: at least a small bathroom, at most a hall the baker still resolves at a few cm per texel. */
export const ROOM_LIMITS = {
  width: { min: 1, max: 30 },
  depth: { min: 1, max: 30 },
  height: { min: 2.2, max: 8 },
} as const;

export type RoomDimension = keyof typeof ROOM_LIMITS;

/** The one room-limit check: validate(), and through it setRoom and scene files, and the room-setup form use it. */
export function withinRoomLimits(key: RoomDimension, value: number): boolean {
  const { min, max } = ROOM_LIMITS[key];
  return Number.isFinite(value) && value >= min && value <= max;
}

export const DEFAULT_REFLECTANCE: Record<SurfaceName, Reflectance> = {
  floor: 0.2,
  ceiling: 0.8,
  north: 0.5,
  south: 0.5,
  west: 0.5,
  east: 0.5,
};

export const DEFAULT_ROOM: Room = { width: 5, depth: 4, height: 2.8, reflectance: DEFAULT_REFLECTANCE };

/** An empty configuration for a room (dimensions are checked by validate(), not here). */
export function createConfiguration(room: Partial<Room> = {}): Configuration {
  return { room: { ...DEFAULT_ROOM, ...room, reflectance: { ...DEFAULT_REFLECTANCE, ...room.reflectance } }, systems: [], nextId: 1 };
}
