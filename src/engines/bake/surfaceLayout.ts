import { SURFACE_NAMES, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';

/**
 * How one room surface maps to its light-map texture. Texel (i, j) has its
 * centre at world `origin + uAxis·(i+0.5)·texelU + vAxis·(j+0.5)·texelV`
 * (docs/baker.md, "Texel → world"). Row j = 0 is the texture's first row
 * (WebGL's bottom row) and the first row of a PFM file, so u runs right and
 * v runs up in every image we write.
 */
export interface SurfaceLayout {
  name: SurfaceName;
  /** Index in SURFACE_NAMES; also the seed salt of this surface's sample stream. */
  index: number;
  /** World point at (u, v) = (0, 0). */
  origin: Vec3;
  /** World axis index (0 = x, 1 = y, 2 = z) that u and v follow, and the axis normal to the surface. */
  uAxisIndex: 0 | 1 | 2;
  vAxisIndex: 0 | 1 | 2;
  normalAxisIndex: 0 | 1 | 2;
  /** Unit normal pointing into the room. */
  normal: Vec3;
  /** Surface extent along u and v, metres. */
  lengthU: number;
  lengthV: number;
  /** Texels along u and v. */
  width: number;
  height: number;
  /** A black one-texel sink of a shaped room's enclosure (shapedRoom/encloseShapedRoom.ts): no part of the room; views and statistics leave it out. */
  sink?: true;
}

/** (u axis, v axis, normal axis, sits on the max side of the normal axis) per surface, as in docs/baker.md. */
export const SURFACE_FRAMES: Record<SurfaceName, [0 | 1 | 2, 0 | 1 | 2, 0 | 1 | 2, boolean]> = {
  floor: [0, 2, 1, false],
  ceiling: [0, 2, 1, true],
  north: [0, 1, 2, false],
  south: [0, 1, 2, true],
  west: [2, 1, 0, false],
  east: [2, 1, 0, true],
};

/**
 * Texels along an edge: enough for the requested texel size, at least 1, at most `maxTexels` (each
 * edge on its own; the objects' atlas coarsens its square texels by ×1.25 instead, and why the two
 * differ: docs/baker.md, "Texel size of walls and objects").
 */
export function texelCount(length: number, texelSize: number, maxTexels: number): number {
  return Math.max(1, Math.min(maxTexels, Math.ceil(length / texelSize - 1e-9)));
}

/**
 * The six surface layouts of a W×H×D room for a target texel size (metres) and a texture size cap.
 * A shaped room's enclosure (`enclosure` set, shapedRoom/encloseShapedRoom.ts) has black sinks of
 * one texel each: the room's own surfaces are in the objects' atlas.
 */
export function surfaceLayouts(room: { width: number; height: number; depth: number; enclosure?: unknown }, texelSize: number, maxTexels: number): SurfaceLayout[] {
  const dims = [room.width, room.height, room.depth];
  const cap = room.enclosure ? 1 : maxTexels;
  return SURFACE_NAMES.map((name, index) => {
    const [u, v, n, onMax] = SURFACE_FRAMES[name];
    const origin: Vec3 = [0, 0, 0];
    origin[n] = onMax ? dims[n] : 0;
    const normal: Vec3 = [0, 0, 0];
    normal[n] = onMax ? -1 : 1;
    return {
      name,
      index,
      origin,
      uAxisIndex: u,
      vAxisIndex: v,
      normalAxisIndex: n,
      normal,
      lengthU: dims[u],
      lengthV: dims[v],
      width: texelCount(dims[u], texelSize, cap),
      height: texelCount(dims[v], texelSize, cap),
      ...(room.enclosure ? { sink: true as const } : {}),
    };
  });
}

/** World position of the centre of texel (i, j) of a surface. */
export function texelCentre(layout: SurfaceLayout, i: number, j: number): Vec3 {
  const p: Vec3 = [layout.origin[0], layout.origin[1], layout.origin[2]];
  p[layout.uAxisIndex] = ((i + 0.5) / layout.width) * layout.lengthU;
  p[layout.vAxisIndex] = ((j + 0.5) / layout.height) * layout.lengthV;
  return p;
}

/** A world vector of the given length along one axis (0 = x, 1 = y, 2 = z): a surface's u or v edge, a texel step, a half edge. */
export function axisVector(axis: 0 | 1 | 2, length: number): Vec3 {
  const v: Vec3 = [0, 0, 0];
  v[axis] = length;
  return v;
}

/** Area of one texel, m². */
export function texelArea(layout: SurfaceLayout): number {
  return (layout.lengthU / layout.width) * (layout.lengthV / layout.height);
}
