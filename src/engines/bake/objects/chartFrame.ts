/**
 * Where a planar chart lies in the world (docs/baker.md, "Rooms of any shape": bright patches on
 * atlas charts): chart-local (u, v) in metres maps to `origin + u·axisU + v·axisV`. The chart's
 * uv is an isometry of its plane (buildCharts.ts: u, v in metres), so the map is fixed by any one
 * of its triangles: [P1 − P0, P2 − P0] = [axisU axisV] · [[u1 − u0, u2 − u0], [v1 − v0, v2 − v0]].
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { Chart } from './buildCharts';
import type { WorldTriangles } from './collectWorldTriangles';

export interface ChartFrame {
  /** World point at chart (u, v) = (0, 0), the corner of the chart's first texel. */
  origin: Vec3;
  /** Unit world directions of chart u and v. */
  axisU: Vec3;
  axisV: Vec3;
  /** Unit front normal (the lit side). */
  normal: Vec3;
  /** Area of the chart's triangles, m². */
  area: number;
}

export function chartFrame(chart: Chart, tris: WorldTriangles): ChartFrame {
  // The chart's largest triangle: the best-conditioned solve.
  let best = 0;
  chart.triangles.forEach((t, i) => {
    if (tris.areas[t] > tris.areas[chart.triangles[best]]) best = i;
  });
  const t = chart.triangles[best];
  const p = (k: number, a: number) => tris.positions[9 * t + 3 * k + a];
  const uv = chart.uv.subarray(6 * best, 6 * best + 6);
  const du1 = uv[2] - uv[0];
  const dv1 = uv[3] - uv[1];
  const du2 = uv[4] - uv[0];
  const dv2 = uv[5] - uv[1];
  const det = du1 * dv2 - du2 * dv1;
  const axisU: Vec3 = [0, 0, 0];
  const axisV: Vec3 = [0, 0, 0];
  const origin: Vec3 = [0, 0, 0];
  for (let a = 0; a < 3; a++) {
    const e1 = p(1, a) - p(0, a);
    const e2 = p(2, a) - p(0, a);
    // Inverse of the 2 × 2 uv matrix applied from the right.
    axisU[a] = (e1 * dv2 - e2 * dv1) / det;
    axisV[a] = (e2 * du1 - e1 * du2) / det;
  }
  for (let a = 0; a < 3; a++) origin[a] = p(0, a) - uv[0] * axisU[a] - uv[1] * axisV[a];
  const area = chart.triangles.reduce((sum, k) => sum + tris.areas[k], 0);
  const normal: Vec3 = [tris.normals[3 * t], tris.normals[3 * t + 1], tris.normals[3 * t + 2]];
  return { origin, axisU, axisV, normal, area };
}
