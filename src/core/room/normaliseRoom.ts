/**
 * A valid room in one orientation: corners turned so the outline has positive orientation
 * (doubleSignedArea > 0, the orientation of today's box outline), with everything that refers to
 * walls (slopes, openings, per-wall reflectances) moved along and each wall remembering the index
 * the author gave it, so problems and surfaces can still name it as written.
 */
import { InputError } from '../inputError';
import { flatPlane, inwardNormal, slopePlane, type CeilingPlane } from './ceilingPlanes';
import { doubleSignedArea, isConvexPolygon, type PlanPoint } from './planPolygon';
import type { OpeningKind, RoomInput, RoomReflectance } from './roomInput';
import { roomProblems } from './roomProblems';

export type RoomRgb = readonly [number, number, number];

export interface RoomWall {
  /** The wall's index in the input outline. */
  inputIndex: number;
  start: PlanPoint;
  end: PlanPoint;
  length: number;
  /** Unit vector start → end, plan. */
  direction: readonly [number, number];
  /** Unit plan normal into the room. */
  inward: readonly [number, number];
  reflectance: RoomRgb;
}

export interface NormalisedSlope {
  inputIndex: number;
  /** Index into Room.walls. */
  wall: number;
  kneeHeight: number;
  pitch: number;
  plane: CeilingPlane;
  reflectance: RoomRgb;
}

export interface NormalisedOpening {
  inputIndex: number;
  /** Index into Room.walls. */
  wall: number;
  /** Distance from Room.walls[wall].start to the opening's near side (measured the normalised way). */
  offset: number;
  width: number;
  sill: number;
  height: number;
  kind: OpeningKind;
}

export interface Room {
  /** Corners with positive orientation; wall k runs from corners[k] to corners[k + 1]. */
  corners: readonly PlanPoint[];
  height: number;
  walls: readonly RoomWall[];
  slopes: readonly NormalisedSlope[];
  openings: readonly NormalisedOpening[];
  /** The flat ceiling first, then the slopes' planes in slope order. */
  ceilingPlanes: readonly CeilingPlane[];
  floorReflectance: RoomRgb;
  ceilingReflectance: RoomRgb;
  /** Was the input outline of negative orientation (and therefore turned)? */
  reversed: boolean;
  convex: boolean;
}

const rgb = (r: RoomReflectance): RoomRgb => (typeof r === 'number' ? [r, r, r] : [r[0], r[1], r[2]]);

/** Reflectance of each input wall, whichever form `walls` takes (three numbers are [r, g, b], never three walls). */
export function wallReflectances(walls: RoomInput['reflectance']['walls'], count: number): RoomRgb[] {
  if (typeof walls === 'number') return Array.from({ length: count }, () => rgb(walls));
  const perWall = !(walls.length === 3 && walls.every((v) => typeof v === 'number'));
  if (!perWall) return Array.from({ length: count }, () => rgb(walls as RoomReflectance));
  return (walls as readonly RoomReflectance[]).map(rgb);
}

/** The room in positive orientation; throws an InputError naming the first problem (roomProblems) when it is not valid. */
export function normaliseRoom(input: RoomInput): Room {
  const problems = roomProblems(input);
  if (problems.length > 0) {
    const p = problems[0];
    throw new InputError(`${p.path}: ${p.message}`, { code: p.code, params: p.params });
  }
  const n = input.outline.length;
  const reversed = doubleSignedArea(input.outline) < 0;
  // Reversed, corner 0 stays first: corners' = c0, c(n−1), …, c1, and wall' j is input wall n − 1 − j run backwards.
  const corners: PlanPoint[] = reversed ? [input.outline[0], ...input.outline.slice(1).reverse()] : [...input.outline];
  const toWall = (inputWall: number): number => (reversed ? n - 1 - inputWall : inputWall);
  const inputReflectance = wallReflectances(input.reflectance.walls, n);
  const walls: RoomWall[] = corners.map((start, k) => {
    const end = corners[(k + 1) % n];
    const length = Math.hypot(end[0] - start[0], end[1] - start[1]);
    const inputIndex = reversed ? n - 1 - k : k;
    return {
      inputIndex,
      start,
      end,
      length,
      direction: [(end[0] - start[0]) / length, (end[1] - start[1]) / length],
      inward: inwardNormal(start, end, 1),
      reflectance: inputReflectance[inputIndex],
    };
  });
  const ceilingReflectance = rgb(input.reflectance.ceiling);
  const slopes: NormalisedSlope[] = (input.slopes ?? []).map((s, i) => {
    const wall = toWall(s.wall);
    return {
      inputIndex: i,
      wall,
      kneeHeight: s.kneeHeight,
      pitch: s.pitch,
      plane: slopePlane(walls[wall].start, walls[wall].end, 1, s.kneeHeight, s.pitch),
      reflectance: s.reflectance !== undefined ? rgb(s.reflectance) : ceilingReflectance,
    };
  });
  const openings: NormalisedOpening[] = (input.openings ?? []).map((o, i) => {
    const wall = toWall(o.wall);
    // A turned wall runs from the other end: the near side is measured from there.
    const offset = reversed ? walls[wall].length - o.offset - o.width : o.offset;
    return { inputIndex: i, wall, offset, width: o.width, sill: o.sill, height: o.height, kind: o.kind };
  });
  return {
    corners,
    height: input.height,
    walls,
    slopes,
    openings,
    ceilingPlanes: [flatPlane(input.height), ...slopes.map((s) => s.plane)],
    floorReflectance: rgb(input.reflectance.floor),
    ceilingReflectance,
    reversed,
    convex: isConvexPolygon(corners),
  };
}
