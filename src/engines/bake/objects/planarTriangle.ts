/**
 * 2D triangle helpers for rasterising charts into the atlas: the exact area of a triangle inside a
 * unit texel square (Sutherland & Hodgman 1974 polygon clipping, then the shoelace formula) and the
 * closest point of a triangle to a point, as barycentric weights (Ericson 2005, "Real-Time
 * Collision Detection", §5.1.5, reduced to the plane).
 */

/** Triangle (a, b, c) given as [ax, ay, bx, by, cx, cy]. */
export type Triangle2 = ArrayLike<number>;

/** Area of triangle ∩ [x0, x0 + 1] × [y0, y0 + 1] (either winding). */
export function overlapWithTexel(tri: Triangle2, x0: number, y0: number): number {
  const minX = Math.min(tri[0], tri[2], tri[4]),
    maxX = Math.max(tri[0], tri[2], tri[4]);
  const minY = Math.min(tri[1], tri[3], tri[5]),
    maxY = Math.max(tri[1], tri[3], tri[5]);
  if (maxX <= x0 || minX >= x0 + 1 || maxY <= y0 || minY >= y0 + 1) return 0;
  if (minX >= x0 && maxX <= x0 + 1 && minY >= y0 && maxY <= y0 + 1) {
    // Wholly inside the texel (the common case for small triangles): no clipping.
    return Math.abs((tri[2] - tri[0]) * (tri[5] - tri[1]) - (tri[4] - tri[0]) * (tri[3] - tri[1])) / 2;
  }
  const poly = clipToTexel(tri, x0, y0);
  if (!poly) return 0;
  let twice = 0;
  const n = poly.length / 2;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    twice += poly[2 * i] * poly[2 * j + 1] - poly[2 * j] * poly[2 * i + 1];
  }
  return Math.abs(twice) / 2;
}

/**
 * Area and centroid of triangle ∩ [x0, x0 + 1] × [y0, y0 + 1] (area 0 and the texel centre when
 * they do not meet): the shoelace formula's centroid, C = Σ (p_i + p_j)(p_i × p_j) / (3 · Σ p_i × p_j).
 */
export function overlapCentroidWithTexel(tri: Triangle2, x0: number, y0: number): { area: number; x: number; y: number } {
  const poly = clipToTexel(tri, x0, y0);
  let [twice, cx, cy] = [0, 0, 0];
  const n = poly ? poly.length / 2 : 0;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    const cross = poly![2 * i] * poly![2 * j + 1] - poly![2 * j] * poly![2 * i + 1];
    twice += cross;
    cx += (poly![2 * i] + poly![2 * j]) * cross;
    cy += (poly![2 * i + 1] + poly![2 * j + 1]) * cross;
  }
  if (twice === 0) return { area: 0, x: x0 + 0.5, y: y0 + 0.5 };
  return { area: Math.abs(twice) / 2, x: cx / (3 * twice), y: cy / (3 * twice) };
}

/** The triangle clipped to the texel square (Sutherland–Hodgman), or null when less than a triangle is left. */
function clipToTexel(tri: Triangle2, x0: number, y0: number): number[] | null {
  let poly: number[] = [tri[0], tri[1], tri[2], tri[3], tri[4], tri[5]];
  // Clip against x ≥ x0, x ≤ x0+1, y ≥ y0, y ≤ y0+1 in turn: [axis, sign, limit] means sign·coordinate ≥ limit.
  const planes: [number, number, number][] = [
    [0, 1, x0],
    [0, -1, -(x0 + 1)],
    [1, 1, y0],
    [1, -1, -(y0 + 1)],
  ];
  for (const [axis, sign, limit] of planes) {
    const out: number[] = [];
    const n = poly.length / 2;
    for (let i = 0; i < n; i++) {
      const px = poly[2 * i],
        py = poly[2 * i + 1];
      const j = (i + 1) % n;
      const qx = poly[2 * j],
        qy = poly[2 * j + 1];
      const dp = sign * (axis === 0 ? px : py) - limit;
      const dq = sign * (axis === 0 ? qx : qy) - limit;
      if (dp >= 0) out.push(px, py);
      if (dp >= 0 !== dq >= 0) {
        const s = dp / (dp - dq);
        out.push(px + s * (qx - px), py + s * (qy - py));
      }
    }
    poly = out;
    if (poly.length < 6) return null;
  }
  return poly;
}

/** Barycentric weights [wa, wb, wc] of the point (px, py) in the triangle's plane (any point, inside or not). */
export function barycentric(tri: Triangle2, px: number, py: number): [number, number, number] {
  const e1x = tri[2] - tri[0],
    e1y = tri[3] - tri[1];
  const e2x = tri[4] - tri[0],
    e2y = tri[5] - tri[1];
  const dx = px - tri[0],
    dy = py - tri[1];
  const det = e1x * e2y - e1y * e2x;
  const wb = (dx * e2y - dy * e2x) / det;
  const wc = (e1x * dy - e1y * dx) / det;
  return [1 - wb - wc, wb, wc];
}

/** Closest point of the (closed) triangle to (px, py): its barycentric weights and the squared distance. */
export function closestOnTriangle(tri: Triangle2, px: number, py: number): { weights: [number, number, number]; distanceSq: number } {
  const ax = tri[0],
    ay = tri[1],
    bx = tri[2],
    by = tri[3],
    cx = tri[4],
    cy = tri[5];
  const abx = bx - ax,
    aby = by - ay,
    acx = cx - ax,
    acy = cy - ay;
  const apx = px - ax,
    apy = py - ay;
  const result = (wa: number, wb: number, wc: number): { weights: [number, number, number]; distanceSq: number } => {
    const qx = wa * ax + wb * bx + wc * cx;
    const qy = wa * ay + wb * by + wc * cy;
    return { weights: [wa, wb, wc], distanceSq: (px - qx) ** 2 + (py - qy) ** 2 };
  };
  const d1 = abx * apx + aby * apy;
  const d2 = acx * apx + acy * apy;
  if (d1 <= 0 && d2 <= 0) return result(1, 0, 0);
  const bpx = px - bx,
    bpy = py - by;
  const d3 = abx * bpx + aby * bpy;
  const d4 = acx * bpx + acy * bpy;
  if (d3 >= 0 && d4 <= d3) return result(0, 1, 0);
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const v = d1 / (d1 - d3);
    return result(1 - v, v, 0);
  }
  const cpx = px - cx,
    cpy = py - cy;
  const d5 = abx * cpx + aby * cpy;
  const d6 = acx * cpx + acy * cpy;
  if (d6 >= 0 && d5 <= d6) return result(0, 0, 1);
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const w = d2 / (d2 - d6);
    return result(1 - w, 0, w);
  }
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const w = (d4 - d3) / (d4 - d3 + (d5 - d6));
    return result(0, 1 - w, w);
  }
  const denom = 1 / (va + vb + vc);
  const v = vb * denom;
  const w = vc * denom;
  return result(1 - v - w, v, w);
}
