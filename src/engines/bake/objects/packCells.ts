/**
 * Shelf packing of chart cells into one atlas (docs/baker.md, "Objects: geometry"): cells sorted by
 * height (then width, then index, so the result is deterministic) are placed left to right in rows
 * ("shelves") as high as their first cell (the NFDH level algorithm: Coffman, Garey, Johnson &
 * Tarjan 1980, "Performance bounds for level-oriented two-dimensional packing algorithms"). A few
 * shelf widths are tried; the atlas is the smallest in area that fits within maxSize × maxSize.
 */

export interface PackedCells {
  width: number;
  height: number;
  /** Lower-left texel of each cell, in input order. */
  x: Int32Array;
  y: Int32Array;
}

/** Sorted order of the cells: tallest first, then widest, then input order. */
function packingOrder(w: ArrayLike<number>, h: ArrayLike<number>): number[] {
  return Array.from({ length: w.length }, (_, i) => i).sort((a, b) => h[b] - h[a] || w[b] - w[a] || a - b);
}

function packShelves(order: number[], w: ArrayLike<number>, h: ArrayLike<number>, shelfWidth: number): PackedCells {
  const x = new Int32Array(w.length);
  const y = new Int32Array(w.length);
  let cx = 0;
  let cy = 0;
  let shelf = 0;
  let used = 0;
  for (const i of order) {
    if (cx > 0 && cx + w[i] > shelfWidth) {
      cy += shelf;
      cx = 0;
      shelf = 0;
    }
    x[i] = cx;
    y[i] = cy;
    cx += w[i];
    shelf = Math.max(shelf, h[i]);
    used = Math.max(used, cx);
  }
  return { width: used, height: cy + shelf, x, y };
}

/**
 * Pack cells of w × h texels without overlap. Returns null when no tried shelf width gives an
 * atlas within maxSize in both directions.
 */
export function packCells(w: ArrayLike<number>, h: ArrayLike<number>, maxSize: number): PackedCells | null {
  if (w.length === 0) return { width: 1, height: 1, x: new Int32Array(0), y: new Int32Array(0) };
  let area = 0;
  let widest = 0;
  for (let i = 0; i < w.length; i++) {
    area += w[i] * h[i];
    widest = Math.max(widest, w[i]);
  }
  if (widest > maxSize) return null;
  const order = packingOrder(w, h);
  const base = Math.max(widest, Math.ceil(Math.sqrt(area)));
  let best: PackedCells | null = null;
  for (let step = 0; step <= 12; step++) {
    const shelfWidth = Math.min(maxSize, Math.max(widest, Math.ceil(base * (0.85 + 0.1 * step))));
    const packed = packShelves(order, w, h, shelfWidth);
    if (packed.height > maxSize) continue;
    const size = packed.width * packed.height;
    const bestSize = best ? best.width * best.height : Infinity;
    if (size < bestSize || (size === bestSize && best && Math.max(packed.width, packed.height) < Math.max(best.width, best.height))) best = packed;
  }
  if (!best) {
    // The widest allowed shelves as a last try.
    const packed = packShelves(order, w, h, maxSize);
    if (packed.height <= maxSize) best = packed;
  }
  return best;
}
