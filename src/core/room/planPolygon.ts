/**
 * Plane geometry of a room's floor outline, in plan coordinates [x, z] (metres; plan x = world
 * x, plan y = world z). Pure functions, double precision, no dependencies.
 */

/** A corner of a floor outline in plan: [x, z], metres. */
export type PlanPoint = readonly [number, number];

/**
 * Twice the signed area by the shoelace formula, Σ (x_i z_{i+1} − x_{i+1} z_i): positive for
 * the orientation of today's box outline [0,0] → [W,0] → [W,D] → [0,D] (north, east, south, west),
 * which is the orientation a normalised room has.
 */
export function doubleSignedArea(points: readonly PlanPoint[]): number {
  let sum = 0;
  for (let i = 0; i < points.length; i++) {
    const a = points[i];
    const b = points[(i + 1) % points.length];
    sum += a[0] * b[1] - b[0] * a[1];
  }
  return sum;
}

/** Cross product (b − a) × (c − a): > 0 when c lies to the left of a → b (in the positive orientation). */
export function orient(a: PlanPoint, b: PlanPoint, c: PlanPoint): number {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

function onSegment(a: PlanPoint, b: PlanPoint, p: PlanPoint): boolean {
  return Math.min(a[0], b[0]) <= p[0] && p[0] <= Math.max(a[0], b[0]) && Math.min(a[1], b[1]) <= p[1] && p[1] <= Math.max(a[1], b[1]);
}

/** Do the closed segments a–b and c–d share a point (crossing, touching or overlapping)? */
export function segmentsIntersect(a: PlanPoint, b: PlanPoint, c: PlanPoint, d: PlanPoint): boolean {
  const o1 = orient(a, b, c);
  const o2 = orient(a, b, d);
  const o3 = orient(c, d, a);
  const o4 = orient(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) return true;
  return (o1 === 0 && onSegment(a, b, c)) || (o2 === 0 && onSegment(a, b, d)) || (o3 === 0 && onSegment(c, d, a)) || (o4 === 0 && onSegment(c, d, b));
}

/** Do the segments a–b and c–d cross at a point inside both (each strictly separates the other's ends)? */
export function segmentsCrossProperly(a: PlanPoint, b: PlanPoint, c: PlanPoint, d: PlanPoint): boolean {
  const o1 = orient(a, b, c);
  const o2 = orient(a, b, d);
  const o3 = orient(c, d, a);
  const o4 = orient(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

/** Distance from p to the closed segment a–b. */
export function distanceToSegment(p: PlanPoint, a: PlanPoint, b: PlanPoint): number {
  const dx = b[0] - a[0];
  const dz = b[1] - a[1];
  const len2 = dx * dx + dz * dz;
  const t = len2 > 0 ? Math.min(1, Math.max(0, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / len2)) : 0;
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dz);
}

/**
 * Is p inside the polygon or on its boundary (within `tolerance` metres of an edge)? Inside by
 * the even–odd crossing rule (Shimrat, CACM 5(8), 1962, with the half-open vertex rule), which
 * holds for any simple polygon of either orientation.
 */
export function pointInPolygon(p: PlanPoint, polygon: readonly PlanPoint[], tolerance = 1e-9): boolean {
  let inside = false;
  const n = polygon.length;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const a = polygon[i];
    const b = polygon[j];
    if (distanceToSegment(p, a, b) <= tolerance) return true;
    if (a[1] > p[1] !== b[1] > p[1] && p[0] < ((b[0] - a[0]) * (p[1] - a[1])) / (b[1] - a[1]) + a[0]) inside = !inside;
  }
  return inside;
}

/** Is the polygon convex (no corner turns against its orientation; straight corners allowed)? */
export function isConvexPolygon(points: readonly PlanPoint[]): boolean {
  const sign = Math.sign(doubleSignedArea(points));
  const n = points.length;
  for (let i = 0; i < n; i++) {
    const turn = orient(points[i], points[(i + 1) % n], points[(i + 2) % n]);
    // A tolerance relative to the edges: a corner of a nanometre is straight.
    const scale = Math.hypot(points[(i + 1) % n][0] - points[i][0], points[(i + 1) % n][1] - points[i][1]) * Math.hypot(points[(i + 2) % n][0] - points[(i + 1) % n][0], points[(i + 2) % n][1] - points[(i + 1) % n][1]);
    if (turn * sign < -1e-12 * scale) return false;
  }
  return true;
}
