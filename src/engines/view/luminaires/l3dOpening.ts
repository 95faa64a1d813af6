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
 * LDT's), else 0: the object is flat.
 */
export function l3dOpening(body: Pick<L3dBody, 'primaryObject' | 'primaryAxisX'>, roll: number): Photometry['luminousOpening'] {
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
