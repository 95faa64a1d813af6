import type { Photometry } from '../../../core/photometry/types';
import type { L3dBody } from './l3dBody';

const DEG = Math.PI / 180;

/**
 * The luminous opening the near field splits (Photometry.luminousOpening: width along the
 * luminaire's local x, length along its local z; engines/bake/pointSources.ts) from an L3D body's
 * light-emitting object (docs/gldf.md "The L3D's opening in the near field"): its Rectangle
 * (sizeX × sizeY) or Circle (diameter), as it lies in the reference pose (aimed straight down,
 * swivel 0) in the photometry's frame. An unaimed module's frame is its rail's turned by the beam's
 * roll (world = Ry(heading)·Ry(roll)·local, core/model/modules/aim.ts), so the object's sizeX side,
 * `primaryAxisX` in the rail's frame, is turned back by −roll; the opening is axis-aligned, so a
 * rectangle takes the nearer of the two right-angle alignments (sizeX along local x or along local
 * z). Its height is the largest of the object's LuminousHeights (the vertical luminous sides, as an
 * LDT's), else 0: the object is flat. When the object has LightEmittingSurfaces, those faces are
 * the opening instead (surfaceOpening).
 */
export function l3dOpening(body: Pick<L3dBody, 'primaryObject' | 'primaryAxisX' | 'primarySurfacePoints'>, roll: number): Photometry['luminousOpening'] {
  if (body.primarySurfacePoints) return surfaceOpening(body.primarySurfacePoints, roll);
  const object = body.primaryObject;
  const height = object.luminousHeights ? Math.max(...object.luminousHeights) : 0;
  if (object.shape.kind === 'circle') return { width: object.shape.diameter, length: object.shape.diameter, height, shape: 'circular' };
  // Ry(−roll) of the axis: x' = cos r·x − sin r·z, z' = sin r·x + cos r·z.
  const [x, , z] = body.primaryAxisX;
  const r = roll * DEG;
  const alongX = Math.abs(Math.cos(r) * x - Math.sin(r) * z) >= Math.abs(Math.sin(r) * x + Math.cos(r) * z);
  const { sizeX, sizeY } = object.shape;
  return { width: alongX ? sizeX : sizeY, length: alongX ? sizeY : sizeX, height, shape: 'rectangular' };
}

/**
 * The opening of an object's LightEmittingSurfaces: the box their vertices span in the photometry's
 * frame (reference pose, turned back by −roll): its x extent the width, its z extent the length,
 * its y extent the height (0 for flat faces; a box emitting from its sides too gets a tall opening,
 * split into a bottom and a top grid, engines/bake/pointSources.ts), a rectangle.
 */
export function surfaceOpening(points: Float32Array, roll: number): Photometry['luminousOpening'] {
  const r = roll * DEG;
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i + 2 < points.length; i += 3) {
    const [x, y, z] = [points[i], points[i + 1], points[i + 2]];
    const local = [Math.cos(r) * x - Math.sin(r) * z, y, Math.sin(r) * x + Math.cos(r) * z];
    for (let a = 0; a < 3; a++) {
      lo[a] = Math.min(lo[a], local[a]);
      hi[a] = Math.max(hi[a], local[a]);
    }
  }
  // Float32 vertices: sizes to the micrometre.
  const size = (a: number) => (hi[a] >= lo[a] ? Math.round((hi[a] - lo[a]) * 1e6) / 1e6 : 0);
  return { width: size(0), length: size(2), height: size(1), shape: 'rectangular' };
}
