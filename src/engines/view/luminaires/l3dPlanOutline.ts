import { poseL3dBody, type L3dBody } from './l3dBody';

/**
 * The plan's outline of an L3D body (docs/gldf.md "L3D in the plan"): the convex hull, seen from
 * above, of every housing vertex in the reference pose (aimed straight down), as [x, z] in metres
 * about the photometric centre in the module's mount frame (x along the rail), counterclockwise
 * in (x, z). Andrew's monotone chain (A. M. Andrew, "Another efficient algorithm for convex hulls
 * in two dimensions", Information Processing Letters 9(5), 1979), O(n log n).
 */
export function l3dPlanOutline(body: L3dBody): [number, number][] {
  const points: [number, number][] = [];
  for (const p of poseL3dBody(body, body.reference).parts) {
    if (p.role !== 'housing') continue;
    for (let i = 0; i < p.positions.length; i += 3) points.push([p.positions[i], p.positions[i + 2]]);
  }
  return convexHull(points);
}

/** The convex hull of plan points, counterclockwise in (x, z), without collinear points; fewer than three distinct points come back as they are. */
export function convexHull(input: readonly [number, number][]): [number, number][] {
  const pts = [...new Map(input.map((p) => [`${p[0]},${p[1]}`, p])).values()].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  if (pts.length < 3) return pts;
  const cross = (o: [number, number], a: [number, number], b: [number, number]) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const chain = (list: [number, number][]) => {
    const out: [number, number][] = [];
    for (const p of list) {
      while (out.length >= 2 && cross(out[out.length - 2], out[out.length - 1], p) <= 0) out.pop();
      out.push(p);
    }
    out.pop();
    return out;
  };
  return [...chain(pts), ...chain([...pts].reverse())];
}
