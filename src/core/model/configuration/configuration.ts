/**
 * The configuration: everything the user builds, as plain immutable data.
 * Positions of modules along rails follow from the rail's distribution
 * (src/core/model/rails/distribution.ts), or, on a rail the user arranged by hand, from each
 * module's free `offset` (src/core/model/rails/freePositions.ts); validate() judges both.
 */
import type { Distribution } from '../catalogSchema/railSystemSchema';
import type { Reflectance, Rgb, SurfaceName } from '../lightingScene/lightingScene';
import type { TriangleMesh } from '../../mesh/triangleMesh';
import type { PlanPoint } from '../../room/planPolygon';
import type { RoomOpening, RoomSlope } from '../../room/roomInput';
import type { DaylightSettings, TransmittanceValue } from './daylightSettings';

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
  /**
   * A room that is not a plain box (issue 29, docs/model.md "Room shape"); absent: the box
   * [0, width] × [0, depth], today's fast path. When present, its outline's bounding box is
   * [0, width] × [0, depth] (the editor keeps it there, validate() refuses anything else), so
   * everything that only needs the room's extent keeps reading width and depth.
   */
  shape?: RoomShape;
}

/** The floor outline, roof slopes and openings of a room of any shape (src/core/room, "Version 3 room" in docs/scene-format.md). */
export interface RoomShape {
  /** Corners [x, z], metres, either orientation; wall i runs from corner i to corner i + 1. */
  readonly outline: readonly PlanPoint[];
  readonly slopes: readonly RoomSlope[];
  readonly openings: readonly ShapeOpening[];
  /**
   * One finish per wall in outline order. Absent: each wall takes the box wall (north, east,
   * south, west) whose inward normal is nearest its own, so a rectangle keeps today's finishes.
   */
  readonly wallReflectance?: readonly Reflectance[];
}

/**
 * An opening of the room's shape; a window may carry its glazing (scene file version 10,
 * docs/daylight.md): a preset or the normal-incidence transmittance 0 … 1; absent: "double".
 */
export type ShapeOpening = RoomOpening & { readonly transmittance?: TransmittanceValue };

/** The DMX patch of a module (docs/live-control.md); its rules are in core/model/modules/dmxPatch.ts. */
export type DmxResolution = 8 | 16;

export interface DmxPatch {
  readonly universe: number;
  /** First channel, 1..512. */
  readonly address: number;
  /** 8-bit: one level channel; 16-bit: coarse then fine. */
  readonly resolution: DmxResolution;
  /** A CCT channel after the level channel(s); only for tunable types. */
  readonly cct: boolean;
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
  /**
   * Free position (docs/model.md, "Free positions"): distance from the rail start to the module's
   * START, metres. Absent: the rail's distribution places it. A rail's modules are either all free
   * or all distributed. Scene file version 5.
   */
  readonly offset?: number;
  /** Switched off (keeps its level for switching back on); absent: on. Scene file version 7, docs/model.md "Light scenes". */
  readonly on?: boolean;
  /** Catalog colour filter (gel) id in front of the module; absent: none. Scene file version 7, docs/colour-filters.md. */
  readonly filter?: string;
  /** Aim of an adjustable module relative to its rail; absent: straight down. Scene file version 7, docs/model.md "Aiming". */
  readonly aim?: ModuleAim;
}

/**
 * Aim of an adjustable module (catalog `adjustable` limits). Rotation turns the module about the
 * vertical, relative to the rail's direction; tilt swings its optical axis away from straight down.
 */
export interface ModuleAim {
  /** Degrees in [0, 360), counterclockwise seen from above, 0 = tilting toward the rail's direction (+u). */
  readonly rotation: number;
  /** Degrees from straight down, within the type's tilt range. */
  readonly tilt: number;
}

/** What a light scene stores for one module (docs/model.md, "Light scenes"). */
export interface ModuleLook {
  readonly on: boolean;
  /** 0..1, as ModuleInstance.dimming. */
  readonly level: number;
  /** Kelvin; one of the type's ccts. */
  readonly cct: number;
  /** Catalog filter id; absent: none. */
  readonly filter?: string;
}

/** A named light scene (a cue): a stored look of every module, recalled with a crossfade. */
export interface LightScene {
  /** 'q12', from nextId. */
  readonly id: string;
  readonly name: string;
  /** Crossfade time when recalled, seconds in [0, 30]. */
  readonly fade: number;
  /** Module id → look; a module not listed keeps its state when the scene is recalled. */
  readonly looks: Readonly<Record<string, ModuleLook>>;
}

export interface Rail {
  readonly id: string;
  /** Metres, on the catalog's step grid. */
  readonly length: number;
  readonly distribution: Distribution;
  /** In order from the rail's start to its end (free positions too: ascending offsets). */
  readonly modules: readonly ModuleInstance[];
}

/**
 * How rail i+1 hangs on the chain (docs/model.md, "Trees of rails"): joints[i] joins rail i+1 to the
 * connector node at the END of rail `parent` (absent: rail i, the snake). A node holds one connector;
 * every joint at one node names that connector, and each takes one of its ports (a turn).
 */
export interface Joint {
  /** Catalog connector id. */
  readonly connector: string;
  /**
   * Degrees, counterclockwise seen from above positive (a left turn); ±angle of the connector, 0 for
   * straight; a flexible connector: a multiple of its step within ±maxAngle (setJointTurn, scene file version 6);
   * a T or X connector (catalog `ports` > 2): one of −angle, 0, +angle, each port once per node.
   */
  readonly turn: number;
  /**
   * Index of the rail whose end holds the connector this joint goes through, 0 ≤ parent ≤ i (rails are
   * listed parents first); absent: i, the rail just before (a snake). Scene file version 8.
   */
  readonly parent?: number;
}

/**
 * Where a power feed sits along its chain (docs/model.md, "Power feeds"): the start of the
 * first rail, the end of the last one, the connector node joints[k] goes through, or the free
 * end of rail i (a branch's end on a tree; scene file version 8).
 */
export type FeedAt = 'start' | 'end' | { readonly joint: number } | { readonly end: number };

/** A power feed: a feed kit on the rail with its driver (catalog `drivers`). */
export interface Feed {
  /** 'f12', from nextId. */
  readonly id: string;
  readonly at: FeedAt;
  /** Catalog driver id. */
  readonly driver: string;
}

/** How a system hangs: on wire suspensions (`suspension` below the ceiling) or clipped to the ceiling surface. */
export const MOUNTINGS = ['suspended', 'surface'] as const;
export type Mounting = (typeof MOUNTINGS)[number];

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
  /** joints[i] joins rails[i+1] to the node at the end of rails[joints[i].parent ?? i]; length rails.length − 1 (a tree, docs/model.md). */
  readonly joints: readonly Joint[];
  /** At least one; each module's load goes to the nearest feed along the chain (scene file version 4). */
  readonly feeds: readonly Feed[];
  /** 'surface': clipped to the ceiling, `suspension` is kept for switching back but not used (scene file version 4). */
  readonly mounting: Mounting;
  /**
   * Fixing points the user moved (docs/model.md, "Moving fixing points"): the chain coordinate of
   * EVERY suspension or clip point, ascending, replacing the derived ones (suspensionPoints.ts);
   * absent: derived. Scene file version 6.
   */
  readonly fixings?: readonly number[];
}

/** The four walls (docs/scene-format.md: north z = 0, south z = D, west x = 0, east x = W). */
export const WALL_NAMES = ['north', 'south', 'west', 'east'] as const;
export type WallName = (typeof WALL_NAMES)[number];

/** Where an object's mesh comes from: the furniture library (src/core/catalog/furniture) or a mesh the user imported. */
export type ObjectSource = { readonly kind: 'library'; /** Furniture library item id ('dining-table'). */ readonly item: string } | { readonly kind: 'imported'; /** Key in Configuration.importedMeshes ('i7'). */ readonly mesh: string };

/**
 * Where an object stands. Floor: the mesh origin on the floor at (x, z), turned by the object's
 * yaw. Wall: the mesh's back (local z = 0, front toward local +z) flush on the wall, facing into
 * the room; u along the wall in the wall map coordinates of docs/scene-format.md (north/south:
 * u = x, west/east: u = z) and y the height of the mesh origin above the floor (library wall
 * items have their origin at the back's centre).
 */
export type ObjectPlacement = { readonly on: 'floor'; readonly x: number; readonly z: number } | { readonly on: 'wall'; readonly wall: WallName; readonly u: number; readonly y: number };

/** A material's finish: a surface-finish id (src/core/catalog/surface-finishes.json) or linear RGB, each channel in [0, 0.95]. */
export type ObjectFinish = string | Rgb;

/** A piece of furniture or an imported model placed in the room (docs/model.md, "Objects"). */
export interface RoomObject {
  /** 'o12', from nextId. */
  readonly id: string;
  readonly source: ObjectSource;
  readonly placement: ObjectPlacement;
  /** Degrees in [0, 360), counterclockwise seen from above; floor objects only (wall objects: 0). */
  readonly yaw: number;
  /** Uniform scale; 1 = the library item's real dimensions (or the imported mesh's metres). Limits: OBJECT_SCALE_LIMITS. */
  readonly scale: number;
  /** Material name → finish; a material not listed keeps its default (library) or file colour (import). */
  readonly finishes: Readonly<Record<string, ObjectFinish>>;
}

/** The length unit an imported file was read in (the mesh itself is always stored in metres). */
export const MESH_UNITS = ['m', 'cm', 'mm', 'in'] as const;
export type MeshUnits = (typeof MESH_UNITS)[number];

/** A mesh the user imported (OBJ/glTF, src/engines/meshImport), shared by every object made from it. */
export interface ImportedMesh {
  /** File name shown to the user ('kitchen.obj'). */
  readonly name: string;
  /** Object-local metres, y up, origin on the floor (docs/furniture.md, "Imported models"). */
  readonly mesh: TriangleMesh;
  /** Unit the file was read in. */
  readonly units: MeshUnits;
}

/** Uniform scale limits: library items keep plausible real sizes; imports may need more correction. */
export const OBJECT_SCALE_LIMITS = {
  library: { min: 0.5, max: 2 },
  imported: { min: 0.25, max: 4 },
} as const;

export interface Configuration {
  readonly room: Room;
  readonly systems: readonly LightSystem[];
  /** Furniture and imported models in the room (scene file version 3). */
  readonly objects: readonly RoomObject[];
  /** Imported meshes by id ('i7'); each is used by at least one object. */
  readonly importedMeshes: Readonly<Record<string, ImportedMesh>>;
  /** Light scenes in playback order (scene file version 7); absent or empty: none recorded. */
  readonly lightScenes?: readonly LightScene[];
  /** The sky and the sun through the room's windows (scene file version 10, docs/daylight.md); absent: never switched on. */
  readonly daylight?: DaylightSettings;
  /** Next number for generated ids ('s7', 'r8', 'm9', 'o10', 'i11', feeds 'f12'); keeps ids unique and deterministic. */
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
  return { room: { ...DEFAULT_ROOM, ...room, reflectance: { ...DEFAULT_REFLECTANCE, ...room.reflectance } }, systems: [], objects: [], importedMeshes: {}, nextId: 1 };
}
