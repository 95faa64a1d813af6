/** The broad phase of overlap tests on the plan: boxes of rectangles in a uniform grid (validate(), systemProblems). */
import { rectCorners, rectsOverlap, type PlanRect } from '../rails/geometry';

export interface Box {
  minX: number;
  minZ: number;
  maxX: number;
  maxZ: number;
}

export function boxOf(r: PlanRect): Box {
  const c = rectCorners(r);
  const xs = c.map((p) => p[0]);
  const zs = c.map((p) => p[1]);
  return { minX: Math.min(...xs), minZ: Math.min(...zs), maxX: Math.max(...xs), maxZ: Math.max(...zs) };
}

/** Grid cell edge, metres: about a rail's length, so an element covers a few cells. */
const CELL = 1;
/** Elements spanning more cells than this per axis (a hostile catalog's 1 km rail) are tested against all. */
const MAX_CELLS_PER_AXIS = 64;

/**
 * Calls `found(p, q)` for every pair of rectangles that overlap (rectsOverlap),
 * each pair once, after `wanted(p, q)` says the pair still matters. Broad phase:
 * a uniform grid of CELL-metre cells; a pair is examined only in the first
 * cell both boxes share. Boxes that merely touch are never candidates, which is
 * exact: touching or separated boxes mean separated or touching rectangles,
 * and rectsOverlap calls touching rectangles disjoint.
 */
export function forEachOverlap(rects: readonly PlanRect[], stats: { pairTests: number }, found: (p: number, q: number) => 'continue' | 'skip' | 'stop', wanted: (p: number, q: number) => boolean = () => true): void {
  const boxes = rects.map(boxOf);
  const cells = new Map<string, number[]>();
  const oversize: number[] = [];
  const range = (b: Box) => [Math.floor(b.minX / CELL), Math.floor(b.maxX / CELL), Math.floor(b.minZ / CELL), Math.floor(b.maxZ / CELL)];
  boxes.forEach((b, p) => {
    const [x0, x1, z0, z1] = range(b);
    if (!(x1 - x0 <= MAX_CELLS_PER_AXIS && z1 - z0 <= MAX_CELLS_PER_AXIS)) return oversize.push(p);
    for (let x = x0; x <= x1; x++) {
      for (let z = z0; z <= z1; z++) {
        const key = `${x},${z}`;
        const list = cells.get(key);
        if (list) list.push(p);
        else cells.set(key, [p]);
      }
    }
  });
  const test = (p: number, q: number): boolean => {
    const a = boxes[p];
    const b = boxes[q];
    if (a.minX >= b.maxX || b.minX >= a.maxX || a.minZ >= b.maxZ || b.minZ >= a.maxZ) return true;
    const [lo, hi] = p < q ? [p, q] : [q, p];
    if (!wanted(lo, hi)) return true;
    stats.pairTests++;
    return !rectsOverlap(rects[lo], rects[hi]) || found(lo, hi) !== 'stop';
  };
  for (const [key, list] of cells) {
    const [cx, cz] = key.split(',').map(Number);
    for (let u = 0; u < list.length; u++) {
      for (let v = u + 1; v < list.length; v++) {
        const [a, b] = [boxes[list[u]], boxes[list[v]]];
        // Examine the pair only in the first cell both boxes cover.
        if (Math.max(Math.floor(a.minX / CELL), Math.floor(b.minX / CELL)) !== cx || Math.max(Math.floor(a.minZ / CELL), Math.floor(b.minZ / CELL)) !== cz) continue;
        if (!test(list[u], list[v])) return;
      }
    }
  }
  const isOversize = new Set(oversize);
  for (const p of oversize) {
    for (let q = 0; q < rects.length; q++) {
      if (q === p || (isOversize.has(q) && q < p)) continue;
      if (!test(p, q)) return;
    }
  }
}

/** Whether two boxes overlap (touching is not overlapping). */
export const boxesMeet = (a: Box, b: Box) => a.minX < b.maxX && b.minX < a.maxX && a.minZ < b.maxZ && b.minZ < a.maxZ;
