import type { Rgb, SurfaceName, Vec3 } from '../core/model/lightingScene/lightingScene';
import { BOX_FACES } from './boxGeometry';
import { polygonBounds, polygonCentroid } from './occludedFormFactor';
import type { PlacedTriangles } from './referenceObjects';

/** One radiosity patch of a furnished room: a wall rectangle or a small triangle of an object. */
export interface FurnishedPatch {
  kind: 'wall' | 'object';
  /** The wall it lies on (walls only). */
  surface: SurfaceName | null;
  /** Index of the object and of its placed triangle (objects only; −1 for walls). */
  object: number;
  triangle: number;
  /** 4 corners (a wall rectangle, in order round it) or 3 (counterclockwise from the front). */
  vertices: Vec3[];
  centroid: Vec3;
  /** Unit normal of the lit side (into the room for walls). */
  normal: Vec3;
  area: number;
  /** Largest distance between two corners, m. */
  diameter: number;
  reflectance: Rgb;
  bounds: Float64Array;
}

function diameterOf(poly: readonly Vec3[]): number {
  let d = 0;
  for (let i = 0; i < poly.length; i++) {
    for (let j = i + 1; j < poly.length; j++) d = Math.max(d, Math.hypot(poly[i][0] - poly[j][0], poly[i][1] - poly[j][1], poly[i][2] - poly[j][2]));
  }
  return d;
}

function makePatch(kind: 'wall' | 'object', surface: SurfaceName | null, object: number, triangle: number, vertices: Vec3[], normal: Vec3, area: number, reflectance: Rgb): FurnishedPatch {
  return { kind, surface, object, triangle, vertices, centroid: polygonCentroid(vertices), normal, area, diameter: diameterOf(vertices), reflectance, bounds: polygonBounds(vertices) };
}

/** Each face of the box in ⌈extent / patchSize⌉ equal rectangles per axis. */
export function wallPatches(extent: Vec3, patchSize: number, reflectance: Record<SurfaceName, Rgb>): FurnishedPatch[] {
  const out: FurnishedPatch[] = [];
  for (const f of BOX_FACES) {
    const nu = Math.max(1, Math.ceil(extent[f.uAxis] / patchSize - 1e-9));
    const nv = Math.max(1, Math.ceil(extent[f.vAxis] / patchSize - 1e-9));
    const du = extent[f.uAxis] / nu;
    const dv = extent[f.vAxis] / nv;
    const plane = f.side === 0 ? 0 : extent[f.axis];
    const at = (u: number, v: number): Vec3 => {
      const p: Vec3 = [0, 0, 0];
      p[f.axis] = plane;
      p[f.uAxis] = u;
      p[f.vAxis] = v;
      return p;
    };
    for (let iv = 0; iv < nv; iv++) {
      for (let iu = 0; iu < nu; iu++) {
        const u0 = iu * du;
        const v0 = iv * dv;
        const corners = [at(u0, v0), at(u0 + du, v0), at(u0 + du, v0 + dv), at(u0, v0 + dv)];
        out.push(makePatch('wall', f.name, -1, -1, corners, f.normal, du * dv, reflectance[f.name]));
      }
    }
  }
  return out;
}

/**
 * The k² similar triangles of a triangle (a, b, c) cut by k equal steps along each edge:
 * corners P(i, j) = a + (i/k)(b − a) + (j/k)(c − a). Same orientation as the parent.
 */
export function subdivideTriangle(a: Vec3, b: Vec3, c: Vec3, k: number): Vec3[][] {
  const P = (i: number, j: number): Vec3 => [0, 1, 2].map((x) => a[x] + (i / k) * (b[x] - a[x]) + (j / k) * (c[x] - a[x])) as Vec3;
  const out: Vec3[][] = [];
  for (let j = 0; j < k; j++) {
    for (let i = 0; i + j < k; i++) {
      out.push([P(i, j), P(i + 1, j), P(i, j + 1)]);
      if (i + j <= k - 2) out.push([P(i + 1, j), P(i + 1, j + 1), P(i, j + 1)]);
    }
  }
  return out;
}

/**
 * A triangle cut by repeated bisection of its longest edge (Rivara, Int. J. Numer. Meth.
 * Eng. 20, 1984) until no edge exceeds `size`: slivers (a table leg's sides) become a few
 * pieces along their length instead of k² similar slivers. Pieces keep the parent's orientation.
 */
export function bisectTriangle(a: Vec3, b: Vec3, c: Vec3, size: number, out: Vec3[][] = []): Vec3[][] {
  const len = (p: Vec3, q: Vec3): number => Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  const ab = len(a, b);
  const bc = len(b, c);
  const ca = len(c, a);
  const longest = Math.max(ab, bc, ca);
  if (longest <= size) {
    out.push([a, b, c]);
    return out;
  }
  // Rotate so the longest edge is p→q, then split it at its midpoint m: (p, m, r) and (m, q, r).
  const [p, q, r] = longest === ab ? [a, b, c] : longest === bc ? [b, c, a] : [c, a, b];
  const m: Vec3 = [0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2])];
  bisectTriangle(p, m, r, size, out);
  bisectTriangle(m, q, r, size, out);
  return out;
}

/** Every placed object triangle cut into pieces with edges no longer than `patchSize` (bisectTriangle). */
export function objectPatches(placed: PlacedTriangles, patchSize: number): FurnishedPatch[] {
  const out: FurnishedPatch[] = [];
  const c = placed.corners;
  for (let t = 0; t < placed.count; t++) {
    const a: Vec3 = [c[9 * t], c[9 * t + 1], c[9 * t + 2]];
    const b: Vec3 = [c[9 * t + 3], c[9 * t + 4], c[9 * t + 5]];
    const d: Vec3 = [c[9 * t + 6], c[9 * t + 7], c[9 * t + 8]];
    const normal: Vec3 = [placed.normals[3 * t], placed.normals[3 * t + 1], placed.normals[3 * t + 2]];
    const rho: Rgb = [placed.reflectance[3 * t], placed.reflectance[3 * t + 1], placed.reflectance[3 * t + 2]];
    for (const piece of bisectTriangle(a, b, d, patchSize)) out.push(makePatch('object', null, placed.object[t], t, piece, normal, triangleArea(piece), rho));
  }
  return out;
}

function triangleArea([a, b, c]: Vec3[]): number {
  const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
  return 0.5 * Math.hypot(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]);
}
