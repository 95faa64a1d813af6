/**
 * Planar charts for the objects' light-map atlas (docs/baker.md, "Objects: geometry"): edge-connected
 * triangles of one object that are coplanar with the chart's first triangle (normal within 1°,
 * every vertex within 1 mm of its plane) form one chart. Growing from the seed's plane, not from
 * neighbour to neighbour, keeps a finely tessellated curved surface from drifting into one bent
 * chart. Each chart is projected onto its plane with an orthonormal basis (t, b, n), t × b = n, so a
 * counterclockwise triangle stays counterclockwise in (u, v), and the basis is turned to the
 * minimum-area bounding rectangle of the chart (rotating calipers: Toussaint 1983, "Solving geometric
 * problems with the rotating calipers"), with u along the longer side.
 */
import type { WorldTriangles } from './collectWorldTriangles';

/** Normals of one chart differ from its seed's by at most this angle. */
export const CHART_MAX_ANGLE_DEG = 1;
/** Every vertex of a chart lies within this distance (m) of its seed's plane. */
export const CHART_MAX_OFFSET = 1e-3;

export interface Chart {
  /** Index of the object the chart belongs to. */
  object: number;
  /** World triangle indices (WorldTriangles), in growth order. */
  triangles: number[];
  /** u, v (metres) of the 3 corners per chart triangle, 6 numbers each; the chart lies in [0, width] × [0, height]. */
  uv: Float64Array;
  /** Extent along u, metres (≥ height). */
  width: number;
  /** Extent along v, metres. */
  height: number;
}

type V3 = [number, number, number];

const cross = (a: V3, b: V3): V3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: V3, b: V3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const normalize = (a: V3): V3 => {
  const l = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / l, a[1] / l, a[2] / l];
};

/** Convex hull of 2D points (Andrew's monotone chain, Andrew 1979), counterclockwise, no collinear points. */
export function convexHull(points: [number, number][]): [number, number][] {
  const p = [...points].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (p.length < 3) return p;
  const turn = (o: [number, number], a: [number, number], b: [number, number]): number => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const lower: [number, number][] = [];
  for (const q of p) {
    while (lower.length >= 2 && turn(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
    lower.push(q);
  }
  const upper: [number, number][] = [];
  for (let i = p.length - 1; i >= 0; i--) {
    const q = p[i];
    while (upper.length >= 2 && turn(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
    upper.push(q);
  }
  return lower.slice(0, -1).concat(upper.slice(0, -1));
}

/** Angle of the hull edge whose direction gives the smallest bounding rectangle (0 unless another is clearly smaller). */
function minimumAreaAngle(hull: [number, number][]): number {
  const areaAt = (theta: number): number => {
    const c = Math.cos(theta);
    const s = Math.sin(theta);
    let u0 = Infinity,
      u1 = -Infinity,
      v0 = Infinity,
      v1 = -Infinity;
    for (const [x, y] of hull) {
      const u = c * x + s * y;
      const v = -s * x + c * y;
      u0 = Math.min(u0, u);
      u1 = Math.max(u1, u);
      v0 = Math.min(v0, v);
      v1 = Math.max(v1, v);
    }
    return (u1 - u0) * (v1 - v0);
  };
  let best = 0;
  let bestArea = areaAt(0);
  for (let i = 0; i < hull.length; i++) {
    const a = hull[i];
    const b = hull[(i + 1) % hull.length];
    const theta = Math.atan2(b[1] - a[1], b[0] - a[0]);
    const area = areaAt(theta);
    // Keep the plane's own axes (axis-aligned furniture stays axis-aligned) unless clearly better.
    if (area < bestArea * (1 - 1e-6)) {
      best = theta;
      bestArea = area;
    }
  }
  return best;
}

function edgeKey(a: number, b: number): number {
  return a < b ? a * 0x4000000 + b : b * 0x4000000 + a;
}

/** Group the triangles of each object into planar charts and project each chart onto its plane. */
export function buildCharts(tris: WorldTriangles): Chart[] {
  const { positions: P, normals: N, vertexIds, areas } = tris;
  const edges = new Map<number, number[]>();
  for (let t = 0; t < tris.count; t++) {
    for (let c = 0; c < 3; c++) {
      const key = edgeKey(vertexIds[3 * t + c], vertexIds[3 * t + ((c + 1) % 3)]);
      const list = edges.get(key);
      if (list) list.push(t);
      else edges.set(key, [t]);
    }
  }
  const cosMax = Math.cos((CHART_MAX_ANGLE_DEG * Math.PI) / 180);
  const chartOf = new Int32Array(tris.count).fill(-1);
  const charts: Chart[] = [];
  const normalOf = (t: number): V3 => [N[3 * t], N[3 * t + 1], N[3 * t + 2]];
  const vertex = (t: number, c: number): V3 => [P[9 * t + 3 * c], P[9 * t + 3 * c + 1], P[9 * t + 3 * c + 2]];
  for (let seed = 0; seed < tris.count; seed++) {
    if (chartOf[seed] >= 0) continue;
    const id = charts.length;
    const object = tris.objectOfTriangle[seed];
    const ns = normalOf(seed);
    const ds = dot(ns, vertex(seed, 0));
    const members = [seed];
    chartOf[seed] = id;
    for (let q = 0; q < members.length; q++) {
      const t = members[q];
      for (let c = 0; c < 3; c++) {
        const list = edges.get(edgeKey(vertexIds[3 * t + c], vertexIds[3 * t + ((c + 1) % 3)]));
        for (const o of list ?? []) {
          if (chartOf[o] >= 0 || tris.objectOfTriangle[o] !== object) continue;
          if (N[3 * o] * ns[0] + N[3 * o + 1] * ns[1] + N[3 * o + 2] * ns[2] < cosMax) continue;
          let flat = true;
          for (let k = 9 * o; k < 9 * o + 9 && flat; k += 3) flat = Math.abs(P[k] * ns[0] + P[k + 1] * ns[1] + P[k + 2] * ns[2] - ds) <= CHART_MAX_OFFSET;
          if (!flat) continue;
          chartOf[o] = id;
          members.push(o);
        }
      }
    }
    charts.push(projectChart(object, members, vertex, normalOf, areas));
  }
  return charts;
}

function projectChart(object: number, members: number[], vertex: (t: number, c: number) => V3, normalOf: (t: number) => V3, areas: Float64Array): Chart {
  // Area-weighted mean normal: the best plane through a nearly planar chart.
  const sum: V3 = [0, 0, 0];
  for (const t of members) {
    const n = normalOf(t);
    for (let a = 0; a < 3; a++) sum[a] += n[a] * areas[t];
  }
  const n = normalize(sum);
  const helper: V3 = Math.abs(n[1]) < 0.9 ? [0, 1, 0] : [1, 0, 0];
  let t = normalize(cross(helper, n));
  let b = cross(n, t);
  const origin = vertex(members[0], 0);
  const project = (p: V3, tt: V3, bb: V3): [number, number] => {
    const d: V3 = [p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]];
    return [dot(d, tt), dot(d, bb)];
  };
  const points: [number, number][] = [];
  for (const tri of members) for (let c = 0; c < 3; c++) points.push(project(vertex(tri, c), t, b));
  const theta = minimumAreaAngle(convexHull(points));
  if (theta !== 0) {
    const c = Math.cos(theta);
    const s = Math.sin(theta);
    const t2: V3 = [c * t[0] + s * b[0], c * t[1] + s * b[1], c * t[2] + s * b[2]];
    const b2: V3 = [-s * t[0] + c * b[0], -s * t[1] + c * b[1], -s * t[2] + c * b[2]];
    t = t2;
    b = b2;
  }
  const uv = new Float64Array(members.length * 6);
  let u0 = Infinity,
    u1 = -Infinity,
    v0 = Infinity,
    v1 = -Infinity;
  members.forEach((tri, i) => {
    for (let c = 0; c < 3; c++) {
      const [u, v] = project(vertex(tri, c), t, b);
      uv[6 * i + 2 * c] = u;
      uv[6 * i + 2 * c + 1] = v;
      u0 = Math.min(u0, u);
      u1 = Math.max(u1, u);
      v0 = Math.min(v0, v);
      v1 = Math.max(v1, v);
    }
  });
  let width = u1 - u0;
  let height = v1 - v0;
  const swap = height > width;
  for (let i = 0; i < uv.length; i += 2) {
    const u = uv[i] - u0;
    const v = uv[i + 1] - v0;
    // A quarter turn (u, v) → (v, width − u) keeps the winding and puts the longer side along u.
    uv[i] = swap ? v : u;
    uv[i + 1] = swap ? width - u : v;
  }
  if (swap) [width, height] = [height, width];
  return { object, triangles: members, uv, width, height };
}
