import { doubleSignedArea, type PlanPoint } from './planPolygon';

/** The half-plane a·x + b·z + c < 0 of the plan. */
export interface HalfPlane {
  readonly a: number;
  readonly b: number;
  readonly c: number;
}

interface RingPoint {
  p: PlanPoint;
  /** 0: a corner of the polygon inside the half-plane; 1: the boundary enters the half-plane here; −1: it leaves. */
  crossing: 0 | 1 | -1;
}

/** Drops repeated consecutive points and pieces without area. */
function cleanLoop(loop: PlanPoint[]): PlanPoint[] | null {
  const out: PlanPoint[] = [];
  for (const p of loop) {
    const q = out[out.length - 1];
    if (!q || Math.abs(q[0] - p[0]) > 1e-12 || Math.abs(q[1] - p[1]) > 1e-12) out.push(p);
  }
  while (out.length > 1 && Math.abs(out[0][0] - out[out.length - 1][0]) <= 1e-12 && Math.abs(out[0][1] - out[out.length - 1][1]) <= 1e-12) out.pop();
  return out.length >= 3 && Math.abs(doubleSignedArea(out)) > 1e-12 ? out : null;
}

/**
 * The part of a simple polygon of positive orientation inside a half-plane, as simple polygons of
 * positive orientation: more than one where a non-convex polygon (an L, a U) leaves and re-enters
 * it. Sutherland–Hodgman (CACM 17(1), 1974) would join such pieces by zero-width bridges along
 * the line; here the crossings are sorted along the line and paired instead (the line's stretches
 * inside the polygon run between crossings 2k and 2k + 1), and each piece is traced by following
 * the boundary inside the half-plane and the line from each exit to its partner entry, as the
 * Weiler–Atherton clipper does for a single line (SIGGRAPH 1977). A corner exactly on the line
 * counts as outside, so every crossing is a clean sign change.
 */
export function keepHalfPlane(polygon: readonly PlanPoint[], h: HalfPlane): PlanPoint[][] {
  const n = polygon.length;
  const s = polygon.map((p) => h.a * p[0] + h.b * p[1] + h.c);
  const inside = s.map((v) => v < 0);
  if (inside.every(Boolean)) return [[...polygon]];
  if (!inside.some(Boolean)) return [];
  const ring: RingPoint[] = [];
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    if (inside[i]) ring.push({ p: polygon[i], crossing: 0 });
    if (inside[i] !== inside[j]) {
      const t = s[i] / (s[i] - s[j]);
      const a = polygon[i];
      const b = polygon[j];
      ring.push({ p: [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])], crossing: inside[i] ? -1 : 1 });
    }
  }
  // Position of each crossing along the line (direction (−b, a)), sorted and paired.
  const crossings = ring.map((r, k) => k).filter((k) => ring[k].crossing !== 0);
  const along = (k: number) => -h.b * ring[k].p[0] + h.a * ring[k].p[1];
  const sorted = [...crossings].sort((x, y) => along(x) - along(y));
  const partner = new Map<number, number>();
  for (let k = 0; k + 1 < sorted.length; k += 2) {
    partner.set(sorted[k], sorted[k + 1]);
    partner.set(sorted[k + 1], sorted[k]);
  }
  const used = new Set<number>();
  const pieces: PlanPoint[][] = [];
  for (const start of crossings) {
    if (ring[start].crossing !== 1 || used.has(start)) continue;
    const loop: PlanPoint[] = [];
    let k = start;
    // Each step visits a ring point once; the bound guards against a pairing spoilt by rounding.
    for (let steps = 0; steps <= 2 * ring.length; steps++) {
      used.add(k);
      loop.push(ring[k].p);
      if (ring[k].crossing === -1) {
        const next = partner.get(k);
        if (next === undefined || next === start || ring[next].crossing !== 1) break;
        k = next;
        continue;
      }
      k = (k + 1) % ring.length;
      if (k === start) break;
    }
    const clean = cleanLoop(loop);
    if (clean) pieces.push(clean);
  }
  return pieces;
}

/** The part of a polygon inside every half-plane. */
export function keepHalfPlanes(polygon: readonly PlanPoint[], planes: readonly HalfPlane[]): PlanPoint[][] {
  let pieces: PlanPoint[][] = [[...polygon]];
  for (const h of planes) pieces = pieces.flatMap((p) => keepHalfPlane(p, h));
  return pieces;
}
