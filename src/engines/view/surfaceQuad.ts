import type { SurfaceLayout } from '../bake/surfaceLayout';

/** One room surface as a quad: corner positions (xyz × 4), uvs (uv × 4) and two triangles. */
export interface SurfaceQuad {
  positions: number[];
  uvs: number[];
  index: number[];
}

/**
 * The quad covering one surface, with uv = (u/lengthU, v/lengthV) so texel
 * centres land where the baker put them, wound so its front face faces into
 * the room (counterclockwise seen from inside): back-face culling then hides
 * the walls facing away from a camera outside the room.
 */
export function surfaceQuad(l: SurfaceLayout): SurfaceQuad {
  const corner = (u: number, v: number): number[] => {
    const p = [l.origin[0], l.origin[1], l.origin[2]];
    p[l.uAxisIndex] = u * l.lengthU;
    p[l.vAxisIndex] = v * l.lengthV;
    return p;
  };
  const uvs = [
    [0, 0],
    [1, 0],
    [1, 1],
    [0, 1],
  ];
  const pts = uvs.map(([u, v]) => corner(u, v));
  const e1 = pts[1].map((x, i) => x - pts[0][i]);
  const e2 = pts[2].map((x, i) => x - pts[0][i]);
  const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
  const facesIn = n[0] * l.normal[0] + n[1] * l.normal[1] + n[2] * l.normal[2] > 0;
  return { positions: pts.flat(), uvs: uvs.flat(), index: facesIn ? [0, 1, 2, 0, 2, 3] : [0, 2, 1, 0, 3, 2] };
}
