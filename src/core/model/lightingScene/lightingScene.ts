/**
 * Lighting scene, versions 1, 2 and 3: the contract between the configurator, the baker
 * and the command line (docs/scene-format.md). Extend, never break.
 */
import type { Room as ShapedRoom } from '../../room/normaliseRoom';
import type { SceneSky, SceneWindow, TransmittanceValue } from './parseDaylight';

export type Rgb = [number, number, number];
export type Vec3 = [number, number, number];

export const SURFACE_NAMES = ['floor', 'ceiling', 'north', 'south', 'west', 'east'] as const;
export type SurfaceName = (typeof SURFACE_NAMES)[number];

/** A reflectance is a number (grey) or linear RGB, each component in [0, 1). */
export type Reflectance = number | Rgb;

export interface LightingRoom {
  /** x extent, metres */
  width: number;
  /** y extent (floor to ceiling), metres */
  height: number;
  /** z extent, metres */
  depth: number;
  reflectance: Record<SurfaceName, Reflectance>;
  /**
   * Version 3 (issue 29): the room of any shape, normalised (src/core/room/normaliseRoom), in
   * world coordinates. Absent: the box [0, width] × [0, height] × [0, depth]. Present: width and
   * depth are the outline's bounding-box extents and `reflectance` the box finishes it was made
   * from (or the nearest box wall's), kept for readers that only know the box.
   */
  shape?: ShapedRoom;
}

export interface LightingLuminaire {
  /** Path of an IES or LDT file, relative to the scene file (or a URL in the browser). */
  photometry: string;
  /** World position of the photometric centre, metres. */
  position: Vec3;
  /** Degrees; world = Ry(yaw) · Rx(pitch) · Ry(roll) · local (docs/scene-format.md, "Units and frames"). */
  yaw: number;
  pitch: number;
  roll: number;
  /** 0..1 multiplier on intensity; default 1. */
  dimming?: number;
  /** Linear RGB multiplier (e.g. from a CCT); default [1, 1, 1]. */
  color?: Rgb;
  /** Optional stable identifier (the configurator sets it to the module id). */
  id?: string;
}

/**
 * How a luminaire's light leaves it (version 2): 'split' (default) turns a luminous opening
 * larger than 5 cm into a grid of point sources; 'point' uses one point source per luminaire
 * (Radiance's ies2rad point model). docs/scene-format.md, "Version 2".
 */
export const NEAR_FIELD_MODELS = ['split', 'point'] as const;
export type NearField = (typeof NEAR_FIELD_MODELS)[number];
export const DEFAULT_NEAR_FIELD: NearField = 'split';

/**
 * An object in the room (version 2): a mesh file placed on the floor or anywhere in the room.
 * world = T(position) · Ry(yaw) · S(scale) · local (src/core/mesh/placeMesh.ts).
 */
export interface LightingObject {
  /** OBJ (+MTL) or glTF/GLB file relative to the scene file (metres, y up); in the app also `object:<id>` (resolved from the configuration). */
  mesh: string;
  /** World position of the mesh's origin, metres. */
  position: Vec3;
  /** Degrees, counterclockwise seen from above; default 0. */
  yaw: number;
  /** Uniform scale; default 1. */
  scale: number;
  /** Overrides every material of the mesh (grey or linear RGB in [0, 1)); absent: the file's own colours (MTL Kd, glTF base colour). */
  reflectance?: Reflectance;
  /** Optional stable identifier (the configurator sets it to the object id). */
  id?: string;
}

export interface LightingScene {
  /** 1, or 2 when the scene uses a version-2 field (nearField, objects), or 3 when its room has a shape (room.shape). */
  version: 1 | 2 | 3;
  /** Versions 2 and 3; absent means DEFAULT_NEAR_FIELD ('split'). */
  nearField?: NearField;
  room: LightingRoom;
  luminaires: LightingLuminaire[];
  /** Versions 2 and 3; absent or empty: an empty room. */
  objects?: LightingObject[];
  /** Versions 2 and 3 with `windows` (a box, which then has `room.shape`), window openings or a `sky` (docs/daylight.md, "The contract"). */
  daylight?: LightingDaylight;
}

/**
 * Daylight of a scene (issue 30): the sky (absent: no daylight is baked, the windows only let
 * light out), version 2's windows as written, and the `transmittance` written on window openings
 * of `room.shape` by input index (version 2: every window, which becomes opening i of the box's
 * outline; version 3: those that give one, the others are DEFAULT_TRANSMITTANCE, "double").
 */
export interface LightingDaylight {
  sky?: SceneSky;
  windows: SceneWindow[];
  transmittance: Record<number, TransmittanceValue>;
  /**
   * Without a sky: the ground's reflectance of a configuration's daylight that is on while the sun
   * is down (files/lightingDaylight.ts), kept for the daylight factor, whose overcast sky needs no
   * sun (docs/daylight.md, "The shopper's daylight"). Not part of the scene format.
   */
  groundReflectance?: number;
}
