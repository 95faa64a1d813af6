import type { ConnectedPart } from './connectedParts';

/**
 * Most triangle pairs one part's test looks at. A grid cell holds the triangles whose boxes reach
 * it, so a part whose triangles all crowd one cell (a cone of 10 000 sides round its apex) would
 * cost n² pairs; past this budget the search stops and the part keeps the winding its signed volume
 * gives (docs/furniture.md, "Which side of a face is lit", step 4). 10⁶ pairs take about 0.1 s of CPU.
 */
export const SELF_INTERSECTION_PAIR_BUDGET = 1_000_000;

/**
 * Whether two triangles of a closed part cross each other (issue #35: a self-intersecting closed
 * part has no inside that its signed volume could tell, so orientMesh makes it two-sided with a
 * warning). Broad phase: a uniform grid over the part's bounding box, cells twice a triangle's mean size.
 * Narrow phase: two triangles in general position intersect exactly when an edge of one crosses the
 * interior of the other (the ends of their common segment lie on edges), tested with strict signs of
 * orient3d determinants (Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast Robust
 * Geometric Predicates", 1997) against a tolerance: a touch (a corner on a face, coplanar faces in
 * contact, an edge along an edge) is not a crossing. Pairs with a corner in common (by `vertexId`,
 * corners welded by position) are not tested: neighbours around a vertex always touch there.
 * Returns false when the pair budget runs out.
 */
export function partSelfIntersects(positions: Float32Array, indices: Uint32Array, vertexId: Uint32Array, part: ConnectedPart): boolean {
  const tris = part.triangles;
  if (tris.length < 4) return false;
  const grid = triangleGrid(positions, indices, tris);
  if (!grid) return false;
  const { box, range } = grid;
  let pairs = 0;
  for (const [key, cell] of grid.cells) {
    for (let i = 0; i < cell.length; i++) {
      for (let j = i + 1; j < cell.length; j++) {
        if (++pairs > SELF_INTERSECTION_PAIR_BUDGET) return false;
        const a = cell[i];
        const b = cell[j];
        // Each pair once: in the first cell both reach (the low corner of their cell ranges' overlap).
        if (grid.key(Math.max(range[6 * a], range[6 * b]), Math.max(range[6 * a + 1], range[6 * b + 1]), Math.max(range[6 * a + 2], range[6 * b + 2])) !== key) continue;
        if (!boxesOverlap(box, a, b) || shareCorner(indices, vertexId, tris[a], tris[b])) continue;
        if (trianglesCross(positions, indices, tris[a], tris[b])) return true;
      }
    }
  }
  return false;
}

interface TriangleGrid {
  /** Cell key → positions in `part.triangles` of the triangles whose bounding boxes reach the cell. */
  cells: Map<number, number[]>;
  /** Per triangle (position in the part): its bounding box, min x y z then max x y z. */
  box: Float64Array;
  /** Per triangle: the cells its box reaches, first x y z then last x y z. */
  range: Int32Array;
  key: (x: number, y: number, z: number) => number;
}

/**
 * The part's triangles binned by bounding box into a grid of cells twice their mean size; null when
 * the entries would pass the pair budget (triangles as large as the part reach every cell).
 */
function triangleGrid(p: Float32Array, indices: Uint32Array, tris: readonly number[]): TriangleGrid | null {
  const box = new Float64Array(6 * tris.length);
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  tris.forEach((t, k) => {
    for (let a = 0; a < 3; a++) {
      const xs = [0, 1, 2].map((c) => p[3 * indices[3 * t + c] + a]);
      box[6 * k + a] = Math.min(...xs);
      box[6 * k + 3 + a] = Math.max(...xs);
      lo[a] = Math.min(lo[a], box[6 * k + a]);
      hi[a] = Math.max(hi[a], box[6 * k + 3 + a]);
    }
  });
  const size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  // Cells about twice a triangle's mean size: a triangle reaches a few, and a cell on a surface holds a few.
  let meanExtent = 0;
  for (let k = 0; k < tris.length; k++) meanExtent += Math.max(box[6 * k + 3] - box[6 * k], box[6 * k + 4] - box[6 * k + 1], box[6 * k + 5] - box[6 * k + 2]) / tris.length;
  const n = Math.max(1, Math.min(1024, Math.ceil(size / (2 * meanExtent))));
  const cell = size / n || 1;
  const at = (x: number, a: number) => Math.min(n - 1, Math.max(0, Math.floor((x - lo[a]) / cell)));
  const key = (x: number, y: number, z: number) => (x * n + y) * n + z;
  const range = new Int32Array(6 * tris.length);
  const cells = new Map<number, number[]>();
  let entries = 0;
  for (let k = 0; k < tris.length; k++) {
    for (let a = 0; a < 3; a++) {
      range[6 * k + a] = at(box[6 * k + a], a);
      range[6 * k + 3 + a] = at(box[6 * k + 3 + a], a);
    }
    const [x0, y0, z0, x1, y1, z1] = range.subarray(6 * k, 6 * k + 6);
    entries += (x1 - x0 + 1) * (y1 - y0 + 1) * (z1 - z0 + 1);
    if (entries > SELF_INTERSECTION_PAIR_BUDGET) return null;
    for (let x = x0; x <= x1; x++)
      for (let y = y0; y <= y1; y++)
        for (let z = z0; z <= z1; z++) {
          const list = cells.get(key(x, y, z));
          if (list) list.push(k);
          else cells.set(key(x, y, z), [k]);
        }
  }
  return { cells, box, range, key };
}

function boxesOverlap(box: Float64Array, a: number, b: number): boolean {
  for (let i = 0; i < 3; i++) if (box[6 * a + i] > box[6 * b + 3 + i] || box[6 * b + i] > box[6 * a + 3 + i]) return false;
  return true;
}

function shareCorner(indices: Uint32Array, vertexId: Uint32Array, a: number, b: number): boolean {
  for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) if (vertexId[indices[3 * a + i]] === vertexId[indices[3 * b + j]]) return true;
  return false;
}

/**
 * Whether an edge of triangle s crosses the interior of triangle t, or one of t's edges crosses s.
 * The determinants of float32 corners are nearly exact in doubles (a difference of two floats is
 * exact, the products round at 1e-16), so a touch gives 0 to rounding: values within 1e-10 of the
 * pair's size cubed count as zero.
 */
function trianglesCross(p: Float32Array, indices: Uint32Array, s: number, t: number): boolean {
  const s0 = 3 * indices[3 * s];
  const s1 = 3 * indices[3 * s + 1];
  const s2 = 3 * indices[3 * s + 2];
  const t0 = 3 * indices[3 * t];
  const t1 = 3 * indices[3 * t + 1];
  const t2 = 3 * indices[3 * t + 2];
  let size = 0;
  for (let a = 0; a < 3; a++) {
    const lo = Math.min(p[s0 + a], p[s1 + a], p[s2 + a], p[t0 + a], p[t1 + a], p[t2 + a]);
    const hi = Math.max(p[s0 + a], p[s1 + a], p[s2 + a], p[t0 + a], p[t1 + a], p[t2 + a]);
    size = Math.max(size, hi - lo);
  }
  const eps = 1e-10 * size ** 3;
  return (
    edgeCrosses(p, s0, s1, t0, t1, t2, eps) ||
    edgeCrosses(p, s1, s2, t0, t1, t2, eps) ||
    edgeCrosses(p, s2, s0, t0, t1, t2, eps) ||
    edgeCrosses(p, t0, t1, s0, s1, s2, eps) ||
    edgeCrosses(p, t1, t2, s0, s1, s2, eps) ||
    edgeCrosses(p, t2, t0, s0, s1, s2, eps)
  );
}

/** Segment q0–q1 passes strictly through the triangle a, b, c (offsets into p): its ends on opposite sides of the plane, and the three edge tests of one strict sign. */
function edgeCrosses(p: Float32Array, q0: number, q1: number, a: number, b: number, c: number, eps: number): boolean {
  const s0 = orient3d(p, a, b, c, q0);
  const s1 = orient3d(p, a, b, c, q1);
  if (!((s0 > eps && s1 < -eps) || (s0 < -eps && s1 > eps))) return false;
  const e0 = orient3d(p, q0, q1, a, b);
  const e1 = orient3d(p, q0, q1, b, c);
  const e2 = orient3d(p, q0, q1, c, a);
  return (e0 > eps && e1 > eps && e2 > eps) || (e0 < -eps && e1 < -eps && e2 < -eps);
}

/** Six times the signed volume of the tetrahedron a, b, c, d (offsets into p): (a − d)·((b − d) × (c − d)). */
function orient3d(p: Float32Array, a: number, b: number, c: number, d: number): number {
  const ax = p[a] - p[d];
  const ay = p[a + 1] - p[d + 1];
  const az = p[a + 2] - p[d + 2];
  const bx = p[b] - p[d];
  const by = p[b + 1] - p[d + 1];
  const bz = p[b + 2] - p[d + 2];
  const cx = p[c] - p[d];
  const cy = p[c + 1] - p[d + 1];
  const cz = p[c + 2] - p[d + 2];
  return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
}
