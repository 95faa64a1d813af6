/**
 * The planar surfaces that bound a room (issue 29): the floor, the part of the flat ceiling that
 * is lowest, each slope's part, and each wall up to the ceiling above it (a gable wall under two
 * slopes is a pentagon), with the openings as holes in their walls. Each surface comes in world
 * coordinates and in its own orthonormal frame (metres on the surface), so a baker or solver can
 * lay texels or patches on it.
 */
import { planeHeight, type CeilingPlane } from './ceilingPlanes';
import { keepHalfPlanes, type HalfPlane } from './keepHalfPlane';
import { doubleSignedArea, type PlanPoint } from './planPolygon';
import type { NormalisedOpening, Room, RoomRgb } from './normaliseRoom';
import type { OpeningKind } from './roomInput';

export type Point3 = [number, number, number];

export type SurfaceKind = 'floor' | 'ceiling' | 'slope' | 'wall';

/** An orthonormal frame in a surface's plane: world = origin + s·u + t·v. */
export interface SurfaceFrame {
  origin: Point3;
  u: Point3;
  v: Point3;
}

export interface SurfaceOpening {
  inputIndex: number;
  kind: OpeningKind;
  /** The opening's rectangle in world coordinates and in the wall's frame (same corner order). */
  polygon: Point3[];
  polygon2d: PlanPoint[];
  area: number;
}

export interface RoomSurface {
  /** 'floor', 'ceiling', 'slope-<i>' or 'wall-<i>', i as in the input. */
  id: string;
  kind: SurfaceKind;
  /** The wall's or slope's index in the input; −1 for the floor and the flat ceiling. */
  inputIndex: number;
  /** The outer boundaries (several where a ceiling part falls apart), each counterclockwise seen from inside the room. */
  polygons: Point3[][];
  /** The same in `frame` coordinates. */
  polygons2d: PlanPoint[][];
  /** Openings cut out of a wall (empty elsewhere). */
  openings: SurfaceOpening[];
  frame: SurfaceFrame;
  /** Unit normal pointing into the room, and its opposite. */
  inward: Point3;
  outward: Point3;
  /** Area, m², without the openings. */
  area: number;
  reflectance: RoomRgb;
}

const sub = (a: Point3, b: Point3): Point3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: Point3, b: Point3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * Newell's normal of a planar polygon (its direction follows the winding; Sutherland, Sproull &
 * Schumacker 1974): twice the polygon's area vector, so its length is twice the area.
 */
export function newellNormal(poly: readonly Point3[]): Point3 {
  const n: Point3 = [0, 0, 0];
  for (let i = 0; i < poly.length; i++) {
    const a = poly[i];
    const b = poly[(i + 1) % poly.length];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

/** Area of a planar polygon in its frame's coordinates. */
const area2d = (poly: readonly PlanPoint[]): number => Math.abs(doubleSignedArea(poly)) / 2;

function toFrame(frame: SurfaceFrame, p: Point3): PlanPoint {
  const d = sub(p, frame.origin);
  return [dot(d, frame.u), dot(d, frame.v)];
}

/** A surface from world polygons: each turned counterclockwise as seen from inside, and mapped into the frame. */
function surface(id: string, kind: SurfaceKind, inputIndex: number, polygons: Point3[][], frame: SurfaceFrame, inward: Point3, reflectance: RoomRgb, openings: SurfaceOpening[] = []): RoomSurface {
  const turned = polygons.map((p) => (dot(newellNormal(p), inward) < 0 ? [...p].reverse() : p));
  const polygons2d = turned.map((p) => p.map((q) => toFrame(frame, q)));
  const gross = polygons2d.reduce((sum, p) => sum + area2d(p), 0);
  const holes = openings.reduce((sum, o) => sum + o.area, 0);
  return { id, kind, inputIndex, polygons: turned, polygons2d, openings, frame, inward, outward: [-inward[0], -inward[1], -inward[2]], area: gross - holes, reflectance };
}

/** Is plane k the lowest at a plan point, ties going to the lower index: the half-planes that say so (null: nowhere). */
function lowestRegion(planes: readonly CeilingPlane[], k: number): HalfPlane[] | null {
  const out: HalfPlane[] = [];
  const pk = planes[k];
  for (let j = 0; j < planes.length; j++) {
    if (j === k) continue;
    const pj = planes[j];
    const h: HalfPlane = { a: pk.gx - pj.gx, b: pk.gz - pj.gz, c: pk.c - pj.c };
    if (Math.abs(h.a) < 1e-12 && Math.abs(h.b) < 1e-12) {
      // Parallel planes: k is lower everywhere, higher everywhere, or the same plane (the lower index keeps it).
      if (h.c > 1e-12 || (Math.abs(h.c) <= 1e-12 && j < k)) return null;
      continue;
    }
    out.push(h);
  }
  return out;
}

/**
 * The top of a wall in its frame: the lowest ceiling plane along it, as [u, height] from u = 0 to
 * its length, with a point wherever the lowest plane changes (the ceiling is concave along any line).
 */
export function wallTop(planes: readonly CeilingPlane[], start: PlanPoint, end: PlanPoint, length: number): PlanPoint[] {
  const lines = planes.map((p) => {
    const a = planeHeight(p, start[0], start[1]);
    return { a, b: (planeHeight(p, end[0], end[1]) - a) / length };
  });
  const us = [0, length];
  for (let i = 0; i < lines.length; i++) {
    for (let j = i + 1; j < lines.length; j++) {
      const db = lines[i].b - lines[j].b;
      if (Math.abs(db) < 1e-15) continue;
      const u = (lines[j].a - lines[i].a) / db;
      if (u > 1e-9 && u < length - 1e-9) us.push(u);
    }
  }
  us.sort((x, y) => x - y);
  const distinct = us.filter((u, i) => i === 0 || u - us[i - 1] > 1e-9);
  const top = distinct.map((u): PlanPoint => [u, Math.min(...lines.map((l) => l.a + l.b * u))]);
  // Keep only the bends: a point on the straight line through its neighbours adds nothing.
  return top.filter((p, i) => {
    if (i === 0 || i === top.length - 1) return true;
    const [a, c] = [top[i - 1], top[i + 1]];
    const onLine = a[1] + ((c[1] - a[1]) * (p[0] - a[0])) / (c[0] - a[0]);
    return Math.abs(onLine - p[1]) > 1e-9;
  });
}

function openingOnWall(o: NormalisedOpening, frame: SurfaceFrame): SurfaceOpening {
  const polygon2d: PlanPoint[] = [
    [o.offset, o.sill],
    [o.offset + o.width, o.sill],
    [o.offset + o.width, o.sill + o.height],
    [o.offset, o.sill + o.height],
  ];
  const polygon = polygon2d.map(([s, t]): Point3 => [frame.origin[0] + s * frame.u[0], t, frame.origin[2] + s * frame.u[2]]);
  return { inputIndex: o.inputIndex, kind: o.kind, polygon, polygon2d, area: o.width * o.height };
}

/** Every planar surface of the room: floor, flat ceiling part, slope parts, walls (in the room's normalised order). */
export function roomSurfaces(room: Room): RoomSurface[] {
  const out: RoomSurface[] = [];
  const corners = room.corners;
  out.push(surface('floor', 'floor', -1, [corners.map(([x, z]): Point3 => [x, 0, z])], { origin: [0, 0, 0], u: [1, 0, 0], v: [0, 0, 1] }, [0, 1, 0], room.floorReflectance));
  room.ceilingPlanes.forEach((plane, k) => {
    const region = lowestRegion(room.ceilingPlanes, k);
    if (!region) return;
    const pieces = keepHalfPlanes(corners, region).filter((p) => area2d(p) > 1e-9);
    if (pieces.length === 0) return;
    const lift = (p: readonly PlanPoint[]): Point3[] => p.map(([x, z]): Point3 => [x, planeHeight(plane, x, z), z]);
    if (k === 0) {
      out.push(surface('ceiling', 'ceiling', -1, pieces.map(lift), { origin: [0, room.height, 0], u: [1, 0, 0], v: [0, 0, 1] }, [0, -1, 0], room.ceilingReflectance));
      return;
    }
    const slope = room.slopes[k - 1];
    const wall = room.walls[slope.wall];
    const pitch = (slope.pitch * Math.PI) / 180;
    const frame: SurfaceFrame = {
      origin: [wall.start[0], slope.kneeHeight, wall.start[1]],
      u: [wall.direction[0], 0, wall.direction[1]],
      v: [Math.cos(pitch) * wall.inward[0], Math.sin(pitch), Math.cos(pitch) * wall.inward[1]],
    };
    const g = Math.hypot(plane.gx, 1, plane.gz);
    out.push(surface(`slope-${slope.inputIndex}`, 'slope', slope.inputIndex, pieces.map(lift), frame, [plane.gx / g, -1 / g, plane.gz / g], slope.reflectance));
  });
  room.walls.forEach((wall, k) => {
    const top = wallTop(room.ceilingPlanes, wall.start, wall.end, wall.length);
    const bottom: PlanPoint[] = [
      [0, 0],
      [wall.length, 0],
    ];
    const outline2d = [...bottom, ...[...top].reverse()].filter((p, i, all) => {
      const q = all[(i + all.length - 1) % all.length];
      return Math.abs(p[0] - q[0]) > 1e-12 || Math.abs(p[1] - q[1]) > 1e-12;
    });
    if (outline2d.length < 3 || area2d(outline2d) < 1e-9) return; // a wall under a slope with knee height 0
    const frame: SurfaceFrame = { origin: [wall.start[0], 0, wall.start[1]], u: [wall.direction[0], 0, wall.direction[1]], v: [0, 1, 0] };
    const polygon = outline2d.map(([s, t]): Point3 => [wall.start[0] + s * wall.direction[0], t, wall.start[1] + s * wall.direction[1]]);
    const openings = room.openings.filter((o) => o.wall === k).map((o) => openingOnWall(o, frame));
    out.push(surface(`wall-${wall.inputIndex}`, 'wall', wall.inputIndex, [polygon], frame, [wall.inward[0], 0, wall.inward[1]], wall.reflectance, openings));
  });
  return out;
}
