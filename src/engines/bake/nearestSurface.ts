import { SURFACE_NAMES, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import { SURFACE_FRAMES } from './surfaceLayout';

/** The surface nearest to a point and the distance to its plane (∞ outside the room's footprint on that plane). */
export function nearestSurface(room: { width: number; height: number; depth: number }, p: Vec3): { surface: SurfaceName; distance: number } {
  const dims = [room.width, room.height, room.depth];
  let best: { surface: SurfaceName; distance: number } = { surface: 'floor', distance: Infinity };
  for (const surface of SURFACE_NAMES) {
    // The surface's plane: normal axis and side from the one frame table (surfaceLayout.ts).
    const [, , axis, onMax] = SURFACE_FRAMES[surface];
    const at = onMax ? dims[axis] : 0;
    // Distance to the surface rectangle (not just its plane): outside the rectangle counts too.
    let d2 = (p[axis] - at) ** 2;
    for (let a = 0; a < 3; a++) {
      if (a === axis) continue;
      const over = Math.max(0, -p[a], p[a] - dims[a]);
      d2 += over * over;
    }
    const distance = Math.sqrt(d2);
    if (distance < best.distance) best = { surface, distance };
  }
  return best;
}
