/**
 * A room of any shape as the lighting-scene contract version 3 describes it (docs/scene-format.md,
 * "Version 3 room"; issue 29): a floor outline, a flat ceiling height, roof slopes standing on
 * walls, openings in walls and reflectances. Indices (walls, corners, slopes, openings) count
 * from 0 in the order the author wrote them; wall i runs from corner i to corner i + 1 and the
 * last wall closes the outline.
 */
import type { PlanPoint } from './planPolygon';

/** A reflectance: a grey value or linear [r, g, b], each in [0, 1). */
export type RoomReflectance = number | readonly [number, number, number];

export interface RoomSlope {
  /** The wall the slope stands on. */
  wall: number;
  /** Height (m) of the slope's lower edge, on the wall's line. */
  kneeHeight: number;
  /** Degrees above horizontal, 0 < pitch < 90, rising into the room. */
  pitch: number;
  /** The slope's own finish; the ceiling's when absent. */
  reflectance?: RoomReflectance;
}

export const OPENING_KINDS = ['door', 'window', 'opening'] as const;
export type OpeningKind = (typeof OPENING_KINDS)[number];

export interface RoomOpening {
  wall: number;
  /** Distance (m) along the wall from its first corner to the opening's near side. */
  offset: number;
  width: number;
  /** Height (m) of the opening's bottom above the floor (0 for a door). */
  sill: number;
  height: number;
  kind: OpeningKind;
}

export interface RoomInput {
  /** Corners [x, z] in metres, either orientation. */
  outline: readonly PlanPoint[];
  /** The flat ceiling, metres above the floor (y = 0). */
  height: number;
  slopes?: readonly RoomSlope[];
  openings?: readonly RoomOpening[];
  reflectance: {
    floor: RoomReflectance;
    ceiling: RoomReflectance;
    /** One for all walls, or one per wall (in outline order). */
    walls: RoomReflectance | readonly RoomReflectance[];
  };
}

/** The rules of issue 29's room model, metres. */
export const ROOM_SHAPE_LIMITS = {
  minCorners: 3,
  maxCorners: 64,
  /** Shortest wall, and closest two corners may come. */
  minWall: 0.1,
  /** Lowest and highest flat ceiling (the scene format's room limits). */
  minHeight: 0.1,
  maxHeight: 500,
  /** Largest |x| or |z| of a corner. */
  maxCoordinate: 500,
} as const;
