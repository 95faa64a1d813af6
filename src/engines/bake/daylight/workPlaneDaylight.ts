/**
 * Illuminance on the work plane (issue 30, the daylight factor's reference plane): points on a
 * grid at WORK_PLANE_HEIGHT above the floor, at least WALL_BAND from every wall — EN 17037:2018's
 * reference plane (0.85 m; the band at the walls as BS EN 17037's calculation grid leaves it,
 * 0.5 m). At each point the direct daylight exactly as a texel's (daylightAtPoint.ts, sight lines
 * through the BVH) plus a final gather of the baked room: cosine-weighted directions about the
 * up normal, each reading ρ·E of the atlas texel it hits (the gather passes' estimator,
 * E = mean ρ·E_hit), nothing where it leaves through a window (that light is the direct part).
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { PlanPoint } from '../../../core/room/planPolygon';
import type { Room } from '../../../core/room/normaliseRoom';
import { pointInsideRoom } from '../../../core/room/ceilingHeightAt';
import type { ObjectRayCaster } from '../objects/createObjectRayCaster';
import type { ObjectAtlas } from '../objects/preparedObjects';
import { LUMINANCE_WEIGHTS } from '../bakedMaps';
import { skyDaylightAt, sunDaylightAt, type DaylightPointContext } from './daylightAtPoint';

export const WORK_PLANE_HEIGHT = 0.85;
export const WALL_BAND = 0.5;
export const WORK_PLANE_SPACING = 0.25;
export const WORK_PLANE_SAMPLES = 256;
const UP: Vec3 = [0, 1, 0];
/** The golden-ratio sequence's step: with the stratified radius it spreads the gather's directions evenly (a Fibonacci lattice). */
const GOLDEN = (Math.sqrt(5) - 1) / 2;

function distanceToSegment(p: PlanPoint, a: PlanPoint, b: PlanPoint): number {
  const [dx, dz] = [b[0] - a[0], b[1] - a[1]];
  const t = Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dz) / (dx * dx + dz * dz)));
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dz);
}

/** The grid's points (world coordinates) inside the outline, WALL_BAND from its walls, under the ceiling; each stands for spacing² of the plane. */
export function workPlanePoints(shape: Room, spacing = WORK_PLANE_SPACING): Vec3[] {
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const out: Vec3[] = [];
  for (let x = Math.min(...xs) + spacing / 2; x < Math.max(...xs); x += spacing) {
    for (let z = Math.min(...zs) + spacing / 2; z < Math.max(...zs); z += spacing) {
      const p: Vec3 = [x, WORK_PLANE_HEIGHT, z];
      if (!pointInsideRoom(shape, p)) continue;
      const near = shape.corners.some((c, k) => distanceToSegment([x, z], c, shape.corners[(k + 1) % shape.corners.length]) < WALL_BAND);
      if (!near) out.push(p);
    }
  }
  return out;
}

/** Y illuminance (lux) at each point (bake coordinates), upward normal: direct daylight + the gather of `total` (RGB lux per atlas texel, the map as shown). */
export function workPlaneIlluminance(points: readonly Vec3[], ctx: DaylightPointContext, caster: ObjectRayCaster, atlas: ObjectAtlas, total: Float32Array, samples = WORK_PLANE_SAMPLES): Float64Array {
  const out = new Float64Array(points.length);
  points.forEach((p, i) => {
    let gathered = 0;
    for (let s = 0; s < samples; s++) {
      const u = (s + 0.5) / samples;
      const phi = 2 * Math.PI * ((s * GOLDEN) % 1);
      const r = Math.sqrt(u);
      const hit = caster.closestHit(p, [r * Math.cos(phi), Math.sqrt(1 - u), r * Math.sin(phi)], 1e4);
      if (!hit || !hit.frontFace) continue;
      const ix = Math.min(atlas.width - 1, Math.floor(hit.atlasUv[0] * atlas.width));
      const iy = Math.min(atlas.height - 1, Math.floor(hit.atlasUv[1] * atlas.height));
      const k = iy * atlas.width + ix;
      for (let c = 0; c < 3; c++) gathered += LUMINANCE_WEIGHTS[c] * atlas.reflectance[4 * k + c] * total[3 * k + c];
    }
    out[i] = skyDaylightAt(ctx, p, UP) + sunDaylightAt(ctx, p, UP) + gathered / samples;
  });
  return out;
}
