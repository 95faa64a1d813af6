/**
 * Patches on the planar surfaces of a room of any shape (src/core/room/roomSurfaces.ts): each
 * surface is cut by a square lattice of `patchSize` cells in its own frame (metres on the
 * surface), each cell minus the surface's openings and clipped to the surface's polygon; each
 * opening is cut the same way into patches of its own, which absorb all light (an opening lets
 * light out and nothing in, issue 29). A patch is any simple polygon (a cell of a slanted or
 * notched surface is not a rectangle); its light is found on sub-pieces, the same lattice cut finer.
 */
import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import type { PlanPoint } from '../core/room/planPolygon';
import type { RoomSurface, SurfaceFrame } from '../core/room/roomSurfaces';

export type RoomPatchKind = RoomSurface['kind'] | 'opening';

/** A rectangle [s0, s1] × [t0, t1] in a surface's frame. */
type Rect = [number, number, number, number];

export interface RoomPatch {
  /** Index of the surface in the solver's surface list. */
  surface: number;
  kind: RoomPatchKind;
  /** Input index of the opening (kind 'opening'), else −1. */
  opening: number;
  /** World corners (counterclockwise seen from the room; Lambert's integral takes either). */
  vertices: Vec3[];
  /** The same in the surface's frame. */
  polygon2d: PlanPoint[];
  frame: SurfaceFrame;
  /** Unit normal into the room. */
  normal: Vec3;
  area: number;
  centroid: Vec3;
  /** Largest distance between two corners. */
  diameter: number;
  reflectance: Rgb;
}

/** A piece of a patch: its polygon (world), area and centroid. */
export interface PatchPiece {
  vertices: Vec3[];
  area: number;
  centroid: Vec3;
}

const toWorld = (f: SurfaceFrame, [s, t]: PlanPoint): Vec3 => [f.origin[0] + s * f.u[0] + t * f.v[0], f.origin[1] + s * f.u[1] + t * f.v[1], f.origin[2] + s * f.u[2] + t * f.v[2]];

/** Signed area and centroid of a 2D polygon (the shoelace formula and its first moments). */
function areaCentroid(poly: readonly PlanPoint[]): { area: number; c: PlanPoint } {
  let a = 0;
  let cx = 0;
  let cy = 0;
  for (let i = 0; i < poly.length; i++) {
    const p = poly[i];
    const q = poly[(i + 1) % poly.length];
    const cross = p[0] * q[1] - q[0] * p[1];
    a += cross;
    cx += (p[0] + q[0]) * cross;
    cy += (p[1] + q[1]) * cross;
  }
  return a === 0 ? { area: 0, c: poly[0] } : { area: a / 2, c: [cx / (3 * a), cy / (3 * a)] };
}

/**
 * A polygon clipped to an axis-aligned rectangle (Sutherland & Hodgman, CACM 17(1), 1974: the
 * window is convex, so the result is exact; a non-convex polygon that enters the window twice
 * comes back joined by an edge traversed both ways, which changes neither its area, its even–odd
 * inside test nor Lambert's contour integral).
 */
export function clipToRect(poly: readonly PlanPoint[], [s0, s1, t0, t1]: Rect): PlanPoint[] {
  let out: PlanPoint[] = [...poly];
  const edges: [number, number, number][] = [
    [0, 1, -s0],
    [0, -1, s1],
    [1, 1, -t0],
    [1, -1, t1],
  ];
  for (const [axis, sign, offset] of edges) {
    const input = out;
    out = [];
    const inside = (p: PlanPoint) => sign * p[axis] + offset >= 0;
    for (let i = 0; i < input.length; i++) {
      const a = input[i];
      const b = input[(i + 1) % input.length];
      const ia = inside(a);
      const ib = inside(b);
      if (ia) out.push(a);
      if (ia !== ib) {
        const ha = sign * a[axis] + offset;
        const hb = sign * b[axis] + offset;
        const t = ha / (ha - hb);
        out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
      }
    }
    if (out.length === 0) return out;
  }
  return out;
}

/** A rectangle minus another: up to four rectangles. */
function rectMinus(r: Rect, h: Rect): Rect[] {
  const [s0, s1, t0, t1] = r;
  const [a0, a1, b0, b1] = h;
  if (a0 >= s1 || a1 <= s0 || b0 >= t1 || b1 <= t0) return [r];
  const out: Rect[] = [];
  const lo = Math.max(t0, b0);
  const hi = Math.min(t1, b1);
  if (lo > t0) out.push([s0, s1, t0, lo]);
  if (hi < t1) out.push([s0, s1, hi, t1]);
  if (a0 > s0) out.push([s0, a0, lo, hi]);
  if (a1 < s1) out.push([a1, s1, lo, hi]);
  return out.filter(([p, q, u, v]) => q - p > 1e-12 && v - u > 1e-12);
}

function boundsOf(polys: readonly (readonly PlanPoint[])[]): Rect {
  const r: Rect = [Infinity, -Infinity, Infinity, -Infinity];
  for (const p of polys) {
    for (const [s, t] of p) {
      r[0] = Math.min(r[0], s);
      r[1] = Math.max(r[1], s);
      r[2] = Math.min(r[2], t);
      r[3] = Math.max(r[3], t);
    }
  }
  return r;
}

/** The cells of a lattice over a rectangle, ⌈side / size⌉ equal parts along each side. */
function lattice(r: Rect, size: number): Rect[] {
  return grid(r, Math.max(1, Math.ceil((r[1] - r[0]) / size - 1e-9)), Math.max(1, Math.ceil((r[3] - r[2]) / size - 1e-9)));
}

/** The cells of an m × n grid over a rectangle. */
function grid([s0, s1, t0, t1]: Rect, m: number, n: number): Rect[] {
  const out: Rect[] = [];
  for (let j = 0; j < n; j++) {
    for (let i = 0; i < m; i++) out.push([s0 + ((s1 - s0) * i) / m, s0 + ((s1 - s0) * (i + 1)) / m, t0 + ((t1 - t0) * j) / n, t0 + ((t1 - t0) * (j + 1)) / n]);
  }
  return out;
}

/** Pieces smaller than this (m²) are dropped: a sliver where a lattice line grazes a corner. */
const MIN_AREA = 1e-10;

function makePatch(surfaceIndex: number, kind: RoomPatchKind, opening: number, poly2d: PlanPoint[], frame: SurfaceFrame, normal: Vec3, reflectance: Rgb): RoomPatch | null {
  const { area, c } = areaCentroid(poly2d);
  if (!(Math.abs(area) > MIN_AREA)) return null;
  const vertices = poly2d.map((p) => toWorld(frame, p));
  let diameter = 0;
  for (const a of vertices) for (const b of vertices) diameter = Math.max(diameter, Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]));
  return { surface: surfaceIndex, kind, opening, vertices, polygon2d: poly2d, frame, normal, area: Math.abs(area), centroid: toWorld(frame, c), diameter, reflectance };
}

/** Every patch of every surface, then the openings' patches. */
export function roomPatches(surfaces: readonly RoomSurface[], patchSize: number): RoomPatch[] {
  const out: RoomPatch[] = [];
  surfaces.forEach((s, k) => {
    const normal: Vec3 = [...s.inward];
    const rho: Rgb = [...s.reflectance];
    const holes = s.openings.map((o) => boundsOf([o.polygon2d]));
    for (const cell of lattice(boundsOf(s.polygons2d), patchSize)) {
      let pieces: Rect[] = [cell];
      for (const h of holes) pieces = pieces.flatMap((r) => rectMinus(r, h));
      for (const r of pieces) {
        for (const poly of s.polygons2d) {
          const p = makePatch(k, s.kind, -1, clipToRect(poly, r), s.frame, normal, rho);
          if (p) out.push(p);
        }
      }
    }
    s.openings.forEach((o, i) => {
      for (const cell of lattice(holes[i], patchSize)) {
        const p = makePatch(k, 'opening', o.inputIndex, clipToRect(o.polygon2d, cell), s.frame, normal, [0, 0, 0]);
        if (p) out.push(p);
      }
    });
  });
  return out;
}

/** The patch cut by an m × m lattice over its bounds: the pieces, each with its area and centroid. */
export function patchPieces(patch: RoomPatch, m: number): PatchPiece[] {
  const out: PatchPiece[] = [];
  for (const cell of grid(boundsOf([patch.polygon2d]), m, m)) {
    const poly = clipToRect(patch.polygon2d, cell);
    if (poly.length < 3) continue;
    const { area, c } = areaCentroid(poly);
    if (!(Math.abs(area) > MIN_AREA * 1e-2)) continue;
    out.push({ vertices: poly.map((p) => toWorld(patch.frame, p)), area: Math.abs(area), centroid: toWorld(patch.frame, c) });
  }
  return out;
}
