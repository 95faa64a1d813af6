/**
 * The room's surfaces as triangles (for a 3D mesh, or a ray tracer's occluders), each wound
 * counterclockwise seen from inside the room, so its normal by the right-hand rule is the
 * surface's inward normal. Floor, ceiling and slope parts by ear clipping (Meisters, Amer. Math.
 * Monthly 82(6), 1975); walls in vertical strips between their bends and the sides of their
 * openings, so an opening is left out exactly and every piece is a quadrilateral.
 */
import { orient, type PlanPoint } from './planPolygon';
import type { Room } from './normaliseRoom';
import { roomSurfaces, wallTop, type Point3, type RoomSurface } from './roomSurfaces';

export interface RoomTriangles {
  surfaces: RoomSurface[];
  /** 9 numbers per triangle: the world corners a, b, c. */
  positions: number[];
  /** Per triangle, the index of its surface in `surfaces`. */
  surfaceOf: number[];
}

/** Triangles of a simple polygon as index triples into it, in the polygon's own winding. */
export function earClip(poly: readonly PlanPoint[]): [number, number, number][] {
  const n = poly.length;
  let area = 0;
  for (let i = 0; i < n; i++) area += poly[i][0] * poly[(i + 1) % n][1] - poly[(i + 1) % n][0] * poly[i][1];
  const sign = area >= 0 ? 1 : -1;
  const left = Array.from({ length: n }, (_, i) => i);
  const out: [number, number, number][] = [];
  const turn = (a: number, b: number, c: number) => sign * orient(poly[a], poly[b], poly[c]);
  const contains = (p: PlanPoint, a: PlanPoint, b: PlanPoint, c: PlanPoint): boolean => sign * orient(a, b, p) >= 0 && sign * orient(b, c, p) >= 0 && sign * orient(c, a, p) >= 0;
  while (left.length > 3) {
    let cut = -1;
    for (let k = 0; k < left.length && cut < 0; k++) {
      const [i, j, l] = [left[(k + left.length - 1) % left.length], left[k], left[(k + 1) % left.length]];
      if (!(turn(i, j, l) > 0)) continue;
      let blocked = false;
      for (const m of left) {
        if (m === i || m === j || m === l) continue;
        const p = poly[m];
        // A corner at the same place as one of the ear's (a pinch) does not block it.
        if ((p[0] === poly[i][0] && p[1] === poly[i][1]) || (p[0] === poly[l][0] && p[1] === poly[l][1])) continue;
        if (contains(p, poly[i], poly[j], poly[l])) {
          blocked = true;
          break;
        }
      }
      if (!blocked) cut = k;
    }
    if (cut < 0) {
      // Only straight (collinear) corners are left to cut: drop one, it spans no area.
      const k = left.findIndex((j, k2) => turn(left[(k2 + left.length - 1) % left.length], j, left[(k2 + 1) % left.length]) === 0);
      if (k < 0) break; // not a simple polygon: give up on the rest rather than loop
      left.splice(k, 1);
      continue;
    }
    out.push([left[(cut + left.length - 1) % left.length], left[cut], left[(cut + 1) % left.length]]);
    left.splice(cut, 1);
  }
  if (left.length === 3 && turn(left[0], left[1], left[2]) > 0) out.push([left[0], left[1], left[2]]);
  return out;
}

const pushTriangle = (out: RoomTriangles, k: number, a: Point3, b: Point3, c: Point3, inward: readonly number[]): void => {
  const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
  const d = n[0] * inward[0] + n[1] * inward[1] + n[2] * inward[2];
  if (Math.abs(d) < 1e-14) return; // no area
  const [p, q] = d > 0 ? [b, c] : [c, b];
  out.positions.push(...a, ...p, ...q);
  out.surfaceOf.push(k);
};

/** Every surface of the room as triangles, openings left out. */
export function roomTriangles(room: Room): RoomTriangles {
  const surfaces = roomSurfaces(room);
  const out: RoomTriangles = { surfaces, positions: [], surfaceOf: [] };
  surfaces.forEach((s, k) => {
    if (s.kind !== 'wall') {
      s.polygons2d.forEach((poly, m) => {
        for (const [a, b, c] of earClip(poly)) pushTriangle(out, k, s.polygons[m][a], s.polygons[m][b], s.polygons[m][c], s.inward);
      });
      return;
    }
    // Each piece a planar quadrilateral wound counterclockwise seen from inside: two triangles.
    for (const [a, b, c, d] of wallQuads(room, s)) {
      pushTriangle(out, k, a, b, c, s.inward);
      pushTriangle(out, k, a, c, d, s.inward);
    }
  });
  return out;
}

/**
 * A wall with its openings left out, as quadrilaterals in vertical strips between its bends and
 * its openings' sides: per strip the wall below each opening, then from the last opening's head
 * (or the floor) up to the wall's top (straight within a strip, the bends being cuts). Corners in
 * the order floor-side left, right, then top right, top left, in the wall's own direction; an
 * opening's sill or head on a strip's edge leaves no piece.
 */
export function wallQuads(room: Room, s: RoomSurface): [Point3, Point3, Point3, Point3][] {
  const out: [Point3, Point3, Point3, Point3][] = [];
  const wall = room.walls.find((w) => w.inputIndex === s.inputIndex)!;
  const top = wallTop(room.ceilingPlanes, wall.start, wall.end, wall.length);
  const topAt = (u: number): number => {
    for (let i = 0; i + 1 < top.length; i++) {
      const [a, b] = [top[i], top[i + 1]];
      if (u <= b[0] + 1e-12) return a[1] + ((b[1] - a[1]) * (u - a[0])) / (b[0] - a[0]);
    }
    return top[top.length - 1][1];
  };
  const cuts = [...top.map((p) => p[0]), ...s.openings.flatMap((o) => [o.polygon2d[0][0], o.polygon2d[1][0]])].sort((x, y) => x - y);
  const at = (u: number, v: number): Point3 => [wall.start[0] + u * wall.direction[0], v, wall.start[1] + u * wall.direction[1]];
  for (let i = 0; i + 1 < cuts.length; i++) {
    const [u0, u1] = [cuts[i], cuts[i + 1]];
    if (!(u1 - u0 > 1e-12)) continue;
    const mid = 0.5 * (u0 + u1);
    // The openings over this strip span it whole (their sides are cuts): the wall between them.
    const gaps = s.openings
      .map((o) => [o.polygon2d[0][0], o.polygon2d[1][0], o.polygon2d[0][1], o.polygon2d[2][1]])
      .filter(([a, b]) => a < mid && mid < b)
      .sort((x, y) => x[2] - y[2]);
    let v = 0;
    for (const [, , sill, head] of gaps) {
      if (sill > v) out.push([at(u0, v), at(u1, v), at(u1, sill), at(u0, sill)]);
      v = head;
    }
    const [t0, t1] = [topAt(u0), topAt(u1)];
    out.push([at(u0, v), at(u1, v), at(u1, t1), at(u0, t0)]);
  }
  return out;
}
