import type { Vec3 } from '../core/model/lightingScene/lightingScene';
import { mayOcclude, segmentClear, type Occluders } from './occluders';
import { pointToPolygonFormFactor } from './pointToPolygonFormFactor';

/**
 * The part of a planar polygon in front of the plane through p with normal n
 * (Sutherland & Hodgman, CACM 17(1), 1974, against one plane). Lambert's contour integral
 * (pointToPolygonFormFactor) is exact only for a polygon wholly in front of the
 * receiving element; an object's triangle can straddle that plane.
 */
export function clipToFront(p: Vec3, n: Vec3, poly: readonly Vec3[]): Vec3[] {
  const h = poly.map((v) => n[0] * (v[0] - p[0]) + n[1] * (v[1] - p[1]) + n[2] * (v[2] - p[2]));
  if (h.every((x) => x >= 0)) return poly as Vec3[];
  if (h.every((x) => x <= 0)) return [];
  const out: Vec3[] = [];
  for (let k = 0; k < poly.length; k++) {
    const k1 = (k + 1) % poly.length;
    const a = poly[k];
    const b = poly[k1];
    if (h[k] >= 0) out.push(a);
    if ((h[k] > 0 && h[k1] < 0) || (h[k] < 0 && h[k1] > 0)) {
      const t = h[k] / (h[k] - h[k1]);
      out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])]);
    }
  }
  return out.length >= 3 ? out : [];
}

/** Unoccluded form factor from the element (p, n) to the part of the polygon in front of it. */
export function frontFormFactor(p: Vec3, n: Vec3, poly: readonly Vec3[]): number {
  const clipped = clipToFront(p, n, poly);
  return clipped.length >= 3 ? pointToPolygonFormFactor(p, n, clipped) : 0;
}

const mid = (a: Vec3, b: Vec3): Vec3 => [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])];

/** The four similar quarters of a triangle (midpoint split) or of a parallelogram (edge midpoints and centre). */
export function splitPolygon(poly: readonly Vec3[]): Vec3[][] {
  if (poly.length === 3) {
    const [a, b, c] = poly;
    const ab = mid(a, b);
    const bc = mid(b, c);
    const ca = mid(c, a);
    return [
      [a, ab, ca],
      [ab, b, bc],
      [ca, bc, c],
      [ab, bc, ca],
    ];
  }
  const [a, b, c, d] = poly;
  const ab = mid(a, b);
  const bc = mid(b, c);
  const cd = mid(c, d);
  const da = mid(d, a);
  const o = mid(ab, cd);
  return [
    [a, ab, o, da],
    [ab, b, bc, o],
    [o, bc, c, cd],
    [da, o, cd, d],
  ];
}

/** [min x, y, z, max x, y, z] of a polygon. */
export function polygonBounds(poly: readonly Vec3[]): Float64Array {
  const b = new Float64Array([Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity]);
  for (const v of poly) {
    for (let a = 0; a < 3; a++) {
      if (v[a] < b[a]) b[a] = v[a];
      if (v[a] > b[3 + a]) b[3 + a] = v[a];
    }
  }
  return b;
}

export function polygonCentroid(poly: readonly Vec3[]): Vec3 {
  const c: Vec3 = [0, 0, 0];
  for (const v of poly) for (let a = 0; a < 3; a++) c[a] += v[a] / poly.length;
  return c;
}

/** Visibility samples: the centre and the corners pulled 1/8 of the way toward it (corners themselves sit on neighbours' edges). */
function samplePoints(poly: readonly Vec3[]): Vec3[] {
  const c = polygonCentroid(poly);
  return [c, ...poly.map((v): Vec3 => [v[0] + 0.125 * (c[0] - v[0]), v[1] + 0.125 * (c[1] - v[1]), v[2] + 0.125 * (c[2] - v[2])])];
}

export interface VisibilityDepth {
  /** Always split the emitter this many times (finer visibility for near emitters). */
  minDepth: number;
  /** Split a piece whose samples disagree (a shadow edge crosses it) at most this deep; at the bottom, F × the visible fraction. */
  maxDepth: number;
}

/**
 * Form factor from a differential element at p (unit normal n) to a planar emitter
 * polygon (unit front normal polyNormal; it emits from its front side only), with
 * occlusion by the objects: F = Σ over pieces of F_exact(piece) × visibility(piece).
 * Each piece's visibility comes from shadow rays to its centre and inset corners; a
 * piece whose rays disagree is split in four, down to `maxDepth`. Unoccluded pieces
 * use Lambert's exact contour integral, so a fully visible emitter is exact
 * (CIE 171:2006 test case 5.7's "configuration factor of the unobstructed portion").
 */
export function occludedFormFactor(p: Vec3, n: Vec3, poly: readonly Vec3[], polyNormal: Vec3, occ: Occluders | null, depth: VisibilityDepth): number {
  // The emitter radiates from its front only; p behind (or in) its plane sees nothing.
  const v0 = poly[0];
  if (polyNormal[0] * (p[0] - v0[0]) + polyNormal[1] * (p[1] - v0[1]) + polyNormal[2] * (p[2] - v0[2]) <= 0) return 0;
  if (!occ || !mayOcclude(occ, p, polygonBounds(poly))) return frontFormFactor(p, n, poly);
  return visiblePart(p, n, poly, polyNormal, occ, depth, 0);
}

function visiblePart(p: Vec3, n: Vec3, poly: readonly Vec3[], polyNormal: Vec3, occ: Occluders, depth: VisibilityDepth, level: number): number {
  // A piece wholly behind the receiver's plane contributes nothing.
  if (poly.every((v) => n[0] * (v[0] - p[0]) + n[1] * (v[1] - p[1]) + n[2] * (v[2] - p[2]) <= 0)) return 0;
  if (level < depth.minDepth) {
    let sum = 0;
    for (const piece of splitPolygon(poly)) sum += visiblePart(p, n, piece, polyNormal, occ, depth, level + 1);
    return sum;
  }
  // Only samples in front of the receiver count: the rest of the piece is clipped away anyway.
  const all = samplePoints(poly);
  const front = all.filter((q) => n[0] * (q[0] - p[0]) + n[1] * (q[1] - p[1]) + n[2] * (q[2] - p[2]) > 0);
  const samples = front.length > 0 ? front : all.slice(0, 1);
  let seen = 0;
  for (const q of samples) if (segmentClear(occ, p, n, q, polyNormal)) seen++;
  if (seen === samples.length) return frontFormFactor(p, n, poly);
  if (seen === 0) return 0;
  if (level < depth.maxDepth) {
    let sum = 0;
    for (const piece of splitPolygon(poly)) sum += visiblePart(p, n, piece, polyNormal, occ, depth, level + 1);
    return sum;
  }
  return (frontFormFactor(p, n, poly) * seen) / samples.length;
}
