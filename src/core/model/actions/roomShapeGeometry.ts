/**
 * The room-shape editor's geometry (issue 29, docs/model.md "Editing the room's shape"): pure
 * edits of a RoomShape that keep everything that refers to walls by index (slopes, openings,
 * per-wall finishes) on the wall it was on. They do not judge the result: the actions run
 * roomProblems on it and settleShape puts it back at the origin.
 */
import type { Configuration, Room, RoomShape, RoomObject, LightSystem } from '../configuration/configuration';
import type { Reflectance } from '../lightingScene/lightingScene';
import { doubleSignedArea, type PlanPoint } from '../../room/planPolygon';
import type { RoomInput } from '../../room/roomInput';
import { shapeRoomInput as configurationShapeRoomInput, wallFinishes as configurationWallFinishes } from '../configuration/roomShape';

export const SHAPE_PRESETS = ['rectangle', 'L', 'U', 'T'] as const;
export type ShapePreset = (typeof SHAPE_PRESETS)[number];

/** Centimetres: the grid the presets' corners are rounded to. */
const cm = (v: number) => Math.round(v * 100) / 100;

/**
 * A preset's outline sized to the room's width W and depth D, corners in the positive
 * orientation of the box (wall 0 is the north wall, z = 0). L: the south-east 40 % × 40 %
 * taken out (the shape of issue 29's example). U: open to the south, the middle third of the
 * southern half taken out. T: the bar along the north wall, half the depth, and a stem of the
 * middle third.
 */
export function presetOutline(preset: ShapePreset, W: number, D: number): PlanPoint[] {
  switch (preset) {
    case 'rectangle':
      return [
        [0, 0],
        [W, 0],
        [W, D],
        [0, D],
      ];
    case 'L':
      return [
        [0, 0],
        [W, 0],
        [W, cm(0.6 * D)],
        [cm(0.6 * W), cm(0.6 * D)],
        [cm(0.6 * W), D],
        [0, D],
      ];
    case 'U':
      return [
        [0, 0],
        [W, 0],
        [W, D],
        [cm((2 * W) / 3), D],
        [cm((2 * W) / 3), cm(D / 2)],
        [cm(W / 3), cm(D / 2)],
        [cm(W / 3), D],
        [0, D],
      ];
    case 'T':
      return [
        [0, 0],
        [W, 0],
        [W, cm(D / 2)],
        [cm((2 * W) / 3), cm(D / 2)],
        [cm((2 * W) / 3), D],
        [cm(W / 3), D],
        [cm(W / 3), cm(D / 2)],
        [0, cm(D / 2)],
      ];
  }
}

/** The room's shape: its own, or the box as a rectangle with nothing on its walls. */
export function currentShape(room: Room): RoomShape {
  return room.shape ?? { outline: presetOutline('rectangle', room.width, room.depth), slopes: [], openings: [] };
}

/** +1 when the outline runs the way the box does (the room to the left of each wall), −1 the other way. */
export function orientationOf(outline: readonly PlanPoint[]): 1 | -1 {
  return doubleSignedArea(outline) >= 0 ? 1 : -1;
}

/** Every wall's finish: its own, else the nearest box wall's (configuration/roomShape.ts, one rule for the editor and validate()). */
export function wallFinishes(room: Room, shape: RoomShape = currentShape(room)): Reflectance[] {
  return configurationWallFinishes({ reflectance: room.reflectance, shape });
}

/** The room as src/core/room reads it: what roomProblems and normaliseRoom judge. */
export function shapeRoomInput(room: Room, shape: RoomShape = currentShape(room)): RoomInput {
  return configurationShapeRoomInput({ ...room, shape });
}

export const wallLength = (outline: readonly PlanPoint[], i: number): number => {
  const a = outline[i];
  const b = outline[(i + 1) % outline.length];
  return Math.hypot(b[0] - a[0], b[1] - a[1]);
};

/** Interior angle (degrees, 0–360) at corner k, between wall k − 1 and wall k, measured inside the room. */
export function cornerAngle(outline: readonly PlanPoint[], k: number): number {
  const n = outline.length;
  const p = outline[(k - 1 + n) % n];
  const c = outline[k];
  const q = outline[(k + 1) % n];
  // Turning angle from the incoming to the outgoing direction, positive toward the room's side.
  const turn = Math.atan2((c[0] - p[0]) * (q[1] - c[1]) - (c[1] - p[1]) * (q[0] - c[0]), (c[0] - p[0]) * (q[0] - c[0]) + (c[1] - p[1]) * (q[1] - c[1]));
  return 180 - (orientationOf(outline) * turn * 180) / Math.PI;
}

const replaceAt = <T>(list: readonly T[], i: number, value: T): T[] => list.map((v, j) => (j === i ? value : v));

/** Corner k moved to p; everything on the walls stays where it was measured from (each wall's first corner). */
export function moveCorner(shape: RoomShape, k: number, p: PlanPoint): RoomShape {
  return { ...shape, outline: replaceAt(shape.outline, k, [p[0], p[1]] as PlanPoint) };
}

/**
 * Wall i split at `at` metres from its first corner: a new corner there, the wall's second part
 * becoming wall i + 1 (later walls move up by one). Openings beyond the split go to the second
 * part (offset measured from the new corner); one across the split refuses (returns a reason).
 * A slope stands on both parts (they lie on one line, so it is the same plane), and both parts
 * keep the wall's finish.
 */
export function splitWall(shape: RoomShape, i: number, at: number): RoomShape | { straddles: number } {
  const a = shape.outline[i];
  const b = shape.outline[(i + 1) % shape.outline.length];
  const t = at / wallLength(shape.outline, i);
  const corner: PlanPoint = [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
  const straddles = shape.openings.findIndex((o) => o.wall === i && o.offset < at - 1e-9 && o.offset + o.width > at + 1e-9);
  if (straddles >= 0) return { straddles };
  const shift = (w: number) => (w > i ? w + 1 : w);
  const outline = [...shape.outline.slice(0, i + 1), corner, ...shape.outline.slice(i + 1)];
  const slopes = shape.slopes.flatMap((s) => (s.wall === i ? [s, { ...s, wall: i + 1 }] : [{ ...s, wall: shift(s.wall) }]));
  const openings = shape.openings.map((o) => (o.wall === i && o.offset >= at - 1e-9 ? { ...o, wall: i + 1, offset: o.offset - at } : { ...o, wall: shift(o.wall) }));
  const wallReflectance = shape.wallReflectance && [...shape.wallReflectance.slice(0, i + 1), shape.wallReflectance[i], ...shape.wallReflectance.slice(i + 1)];
  return { outline, slopes, openings, ...(wallReflectance ? { wallReflectance } : {}) };
}

/**
 * Corner k removed: walls k − 1 and k become one wall from corner k − 1 to corner k + 1. It
 * starts where wall k − 1 did, so it keeps wall k − 1's slope, openings (offsets measured from
 * that corner) and finish; wall k's slope and openings go with the corner.
 */
export function removeCorner(shape: RoomShape, k: number): RoomShape {
  // Wall k is removed; walls after it move down by one (when k = 0 the merged wall is the last, n − 2).
  const renumber = (w: number) => (k === 0 ? w - 1 : w > k ? w - 1 : w);
  const outline = shape.outline.filter((_, j) => j !== k);
  const slopes = shape.slopes.filter((s) => s.wall !== k).map((s) => ({ ...s, wall: renumber(s.wall) }));
  const openings = shape.openings.filter((o) => o.wall !== k).map((o) => ({ ...o, wall: renumber(o.wall) }));
  const wallReflectance = shape.wallReflectance?.filter((_, j) => j !== k);
  return { outline, slopes, openings, ...(wallReflectance ? { wallReflectance } : {}) };
}

/**
 * Wall i given a new length, keeping its direction: the room is stretched along the wall at its
 * second corner, every corner at or beyond that corner (measured along the wall's direction)
 * moving by the change. Walls square to the wall move whole, walls parallel to it lengthen or
 * shorten, so right angles stay right; only walls that cross the stretch line at a slant turn.
 */
export function setWallLength(shape: RoomShape, i: number, length: number): RoomShape {
  const n = shape.outline.length;
  const a = shape.outline[i];
  const b = shape.outline[(i + 1) % n];
  const old = wallLength(shape.outline, i);
  const d: PlanPoint = [(b[0] - a[0]) / old, (b[1] - a[1]) / old];
  const change = length - old;
  const outline = shape.outline.map((p, j): PlanPoint => {
    if (j === i) return p;
    const along = (p[0] - b[0]) * d[0] + (p[1] - b[1]) * d[1];
    return j === (i + 1) % n || along >= -1e-9 ? [p[0] + change * d[0], p[1] + change * d[1]] : p;
  });
  return { ...shape, outline };
}

/**
 * The interior angle at corner k set to `degrees`: wall k turns about corner k, keeping its
 * length, so corner k + 1 moves and wall k + 1 follows it.
 */
export function setCornerAngle(shape: RoomShape, k: number, degrees: number): RoomShape {
  const n = shape.outline.length;
  const c = shape.outline[k];
  const q = shape.outline[(k + 1) % n];
  const delta = ((cornerAngle(shape.outline, k) - degrees) * Math.PI) / 180;
  // Opening the interior angle turns the outgoing wall against the orientation.
  const rot = orientationOf(shape.outline) * delta;
  const [dx, dz] = [q[0] - c[0], q[1] - c[1]];
  const moved: PlanPoint = [c[0] + dx * Math.cos(rot) - dz * Math.sin(rot), c[1] + dx * Math.sin(rot) + dz * Math.cos(rot)];
  return moveCorner(shape, (k + 1) % n, moved);
}

/** The smallest x and z of an outline: how far it must move to start at the origin. */
export function outlineMin(outline: readonly PlanPoint[]): PlanPoint {
  return [Math.min(...outline.map((p) => p[0])), Math.min(...outline.map((p) => p[1]))];
}

function moveObject(o: RoomObject, dx: number, dz: number): RoomObject {
  const p = o.placement;
  if (p.on === 'floor') return { ...o, placement: { ...p, x: p.x + dx, z: p.z + dz } };
  // Wall maps: north and south walls run along x, west and east along z (configuration.ts, ObjectPlacement).
  return { ...o, placement: { ...p, u: p.u + (p.wall === 'north' || p.wall === 'south' ? dx : dz) } };
}

const isBoxRectangle = (shape: RoomShape, W: number, D: number) =>
  shape.slopes.length === 0 && shape.openings.length === 0 && !shape.wallReflectance && shape.outline.length === 4 && presetOutline('rectangle', W, D).every((p, i) => p[0] === shape.outline[i][0] && p[1] === shape.outline[i][1]);

/**
 * The configuration with `shape` as its room, kept in the room's invariant: the outline moved so
 * its bounding box starts at (0, 0), everything placed in the room (systems, floor and wall
 * objects) moved by the same translation so it keeps its place against the walls, and width and
 * depth set to the outline's extents. A plain box rectangle with nothing on its walls is stored
 * as no shape at all: the box, the fast path.
 */
export function settleShape(state: Configuration, shape: RoomShape): Configuration {
  const [minX, minZ] = outlineMin(shape.outline);
  // Float noise below a micrometre is rounded off so repeated edits do not drift.
  const tidy = (v: number) => Math.round(v * 1e6) / 1e6;
  const outline = shape.outline.map((p): PlanPoint => [tidy(p[0] - minX), tidy(p[1] - minZ)]);
  const [dx, dz] = [-minX, -minZ];
  const width = Math.max(...outline.map((p) => p[0]));
  const depth = Math.max(...outline.map((p) => p[1]));
  const settled: RoomShape = { ...shape, outline };
  const room: Room = { ...state.room, width, depth };
  if (isBoxRectangle(settled, width, depth)) delete room.shape;
  else room.shape = settled;
  const moved = dx !== 0 || dz !== 0;
  const systems: readonly LightSystem[] = moved ? state.systems.map((s) => ({ ...s, x: s.x + dx, z: s.z + dz })) : state.systems;
  const objects = moved ? state.objects.map((o) => moveObject(o, dx, dz)) : state.objects;
  return { ...state, room, systems, objects };
}
