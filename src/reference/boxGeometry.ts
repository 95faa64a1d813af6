import type { SurfaceName, Vec3 } from '../core/model/lightingScene/lightingScene';

/** World axis index: 0 = x, 1 = y (up), 2 = z. */
export type Axis = 0 | 1 | 2;

/**
 * One face of the box room as the reference solver parametrises it.
 *
 * A surface point with parameters (u, v) ∈ [0, extent(uAxis)] × [0, extent(vAxis)]
 * (metres, not normalised) is the world point whose `uAxis` coordinate is u, whose
 * `vAxis` coordinate is v and whose `axis` coordinate is 0 (side 0) or the room
 * extent along `axis` (side 1). Patch (iu, iv) covers
 * [iu·hu, (iu+1)·hu] × [iv·hv, (iv+1)·hv] and is stored at index iv·nu + iu.
 */
export interface BoxFace {
  name: SurfaceName;
  /** Axis of the face normal. */
  axis: Axis;
  /** 0: plane at coordinate 0; 1: plane at the room extent along `axis`. */
  side: 0 | 1;
  uAxis: Axis;
  vAxis: Axis;
  /** Unit normal pointing into the room. */
  normal: Vec3;
}

// docs/scene-format.md "Units and frames": floor y=0, ceiling y=H, north z=0, south z=D,
// west x=0, east x=W. u/v follow the plan view for horizontal faces (x, z) and
// put v upward (world y) on the walls.
export const BOX_FACES: readonly BoxFace[] = [
  { name: 'floor', axis: 1, side: 0, uAxis: 0, vAxis: 2, normal: [0, 1, 0] },
  { name: 'ceiling', axis: 1, side: 1, uAxis: 0, vAxis: 2, normal: [0, -1, 0] },
  { name: 'north', axis: 2, side: 0, uAxis: 0, vAxis: 1, normal: [0, 0, 1] },
  { name: 'south', axis: 2, side: 1, uAxis: 0, vAxis: 1, normal: [0, 0, -1] },
  { name: 'west', axis: 0, side: 0, uAxis: 2, vAxis: 1, normal: [1, 0, 0] },
  { name: 'east', axis: 0, side: 1, uAxis: 2, vAxis: 1, normal: [-1, 0, 0] },
];

/** The uniform patch lattice: every face that spans a world axis uses the same divisions along it. */
export interface PatchGrid {
  /** Room extents [W, H, D], metres. */
  extent: Vec3;
  /** Patches along each world axis. */
  count: [number, number, number];
  /** Patch edge length along each world axis, metres (extent / count). */
  size: Vec3;
}

export function makePatchGrid(extent: Vec3, patchSize: number): PatchGrid {
  const count = extent.map((e) => Math.max(1, Math.ceil(e / patchSize - 1e-9))) as [number, number, number];
  const size = extent.map((e, a) => e / count[a]) as Vec3;
  return { extent, count, size };
}

export function patchCount(grid: PatchGrid, face: BoxFace): number {
  return grid.count[face.uAxis] * grid.count[face.vAxis];
}

/** World position of the surface point (u, v) of a face. */
export function facePoint(grid: PatchGrid, face: BoxFace, u: number, v: number): Vec3 {
  const p: Vec3 = [0, 0, 0];
  p[face.axis] = face.side === 0 ? 0 : grid.extent[face.axis];
  p[face.uAxis] = u;
  p[face.vAxis] = v;
  return p;
}
