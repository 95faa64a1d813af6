import type { Vec3 } from '../core/model/lightingScene/lightingScene';

/**
 * Form factor from a differential area at p (unit normal n) to a planar polygon,
 * by Lambert's contour integral (J. H. Lambert, Photometria, 1760; in this form
 * Hottel & Sarofim, Radiative Transfer, 1967; Baum, Rushmeier & Winget, SIGGRAPH
 * 1989): F = (1/2π) Σₖ θₖ · n·(rₖ × rₖ₊₁)/|rₖ × rₖ₊₁|, with rₖ the vectors from p to
 * the vertices and θₖ the angle between consecutive ones. The polygon must lie
 * wholly in front of the element (true for any other face of a box); the sign of
 * the sum depends on the winding, so its magnitude is returned.
 */
export function pointToPolygonFormFactor(p: Vec3, n: Vec3, vertices: readonly Vec3[]): number {
  let sum = 0;
  const m = vertices.length;
  for (let k = 0; k < m; k++) {
    const a = vertices[k];
    const b = vertices[(k + 1) % m];
    const ax = a[0] - p[0];
    const ay = a[1] - p[1];
    const az = a[2] - p[2];
    const bx = b[0] - p[0];
    const by = b[1] - p[1];
    const bz = b[2] - p[2];
    const cx = ay * bz - az * by;
    const cy = az * bx - ax * bz;
    const cz = ax * by - ay * bx;
    const cross = Math.sqrt(cx * cx + cy * cy + cz * cz);
    if (!(cross > 0)) continue; // p on the edge's line: the edge subtends no angle
    // atan2(|a×b|, a·b) is accurate for small and large angles alike.
    const theta = Math.atan2(cross, ax * bx + ay * by + az * bz);
    sum += (theta * (n[0] * cx + n[1] * cy + n[2] * cz)) / cross;
  }
  return Math.abs(sum) / (2 * Math.PI);
}
