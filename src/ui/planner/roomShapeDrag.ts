import type { PlanPoint } from '../../core/room/planPolygon';

/** Dragged corners land on a 5 cm grid: what a tape measure gives, and walls that read as round numbers. */
const GRID_M = 0.05;
/** Within this many screen pixels of a neighbouring corner's x or z, a dragged corner lines up with it (a square corner stays square). */
const ALIGN_PX = 10;

const onGrid = (v: number) => Math.round(v / GRID_M) * GRID_M;

/**
 * Where a corner dragged to `p` goes: each coordinate lined up with the neighbouring corners'
 * (the corners before and after it) when within ALIGN_PX on screen, else on the 5 cm grid.
 */
export function snapCorner(outline: readonly PlanPoint[], corner: number, p: PlanPoint, scale: number): PlanPoint {
  const n = outline.length;
  const neighbours = [outline[(corner - 1 + n) % n], outline[(corner + 1) % n]];
  const snap = (axis: 0 | 1): number => {
    let best: number | null = null;
    for (const q of neighbours) if (Math.abs(q[axis] - p[axis]) * scale <= ALIGN_PX && (best === null || Math.abs(q[axis] - p[axis]) < Math.abs(best - p[axis]))) best = q[axis];
    return best ?? Math.round(onGrid(p[axis]) * 1000) / 1000;
  };
  return [snap(0), snap(1)];
}

/** An opening slid to `offset` along a wall of `length`: kept between the wall's ends, on a centimetre. */
export function slideOpening(offset: number, width: number, length: number): number {
  return Math.round(Math.min(Math.max(offset, 0), length - width) * 100) / 100;
}
