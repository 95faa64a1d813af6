/**
 * The work-plane statistics (lightStats.ts workPlaneStats) in a room of any shape (issue 29): the
 * grid covers the outline's bounding box and leaves out the points outside the outline or above
 * the ceiling there (`covered`); direct light is exact from the baker's point sources, each only
 * where a shadow ray reaches it past the room's own surfaces and the objects (the CPU ray caster
 * over the enclosure's BVH: the L's inner corner shades the plane); the indirect part is the
 * floor's indirect light under the point, read from the atlas texel a ray straight down meets.
 */
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { pointInsideRoom } from '../../core/room/ceilingHeightAt';
import type { BakeScene } from '../bake/bakeScene';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { resolveBakeSettings, type BakeSettings } from '../bake/bakeSettings';
import { directAtPoint } from '../bake/directAtPoint';
import { createObjectRayCaster } from '../bake/objects/createObjectRayCaster';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import { scenePointSources } from '../bake/scenePointSources';
import { encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import type { LitMaps } from '../relight/relightMaps';
import { statsOf, type IlluminanceStats } from './lightStats';

/** Shadow rays start this far above the plane (metres), as in workPlaneStats. */
const SHADOW_RAY_OFFSET = 1e-4;

const Y = (m: ArrayLike<number>, t: number) => LUMINANCE_WEIGHTS[0] * m[3 * t] + LUMINANCE_WEIGHTS[1] * m[3 * t + 1] + LUMINANCE_WEIGHTS[2] * m[3 * t + 2];

/** `objects`: the enclosure's prepared objects (the room's surfaces first), as the baker laid out the atlas `lit` holds. */
export function shapedWorkPlaneStats(
  scene: BakeScene,
  lit: LitMaps,
  height: number,
  spacing: number,
  settings: Partial<BakeSettings>,
  objects: PreparedObjects | null,
): IlluminanceStats & { values: Float32Array; covered: Uint8Array; nx: number; nz: number } {
  const shape = scene.room.shape!;
  const enclosed = encloseShapedRoom(scene);
  const offset = enclosed.room.enclosure!.offset;
  const lamps = scenePointSources(enclosed, resolveBakeSettings(settings));
  const caster = objects && objects.triangleCount > 0 ? createObjectRayCaster(objects) : null;
  const light = lit.maps.objects;
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const [x0, z0] = [Math.min(...xs), Math.min(...zs)];
  const [width, depth] = [Math.max(...xs) - x0, Math.max(...zs) - z0];
  const nx = Math.max(1, Math.round(width / spacing));
  const nz = Math.max(1, Math.round(depth / spacing));
  const values = new Float32Array(nx * nz);
  const covered = new Uint8Array(nx * nz);
  const down: Vec3 = [0, -1, 0];
  for (let k = 0; k < nz; k++) {
    for (let i = 0; i < nx; i++) {
      const x = x0 + ((i + 0.5) / nx) * width;
      const z = z0 + ((k + 0.5) / nz) * depth;
      if (!pointInsideRoom(shape, [x, height, z], 0)) {
        covered[k * nx + i] = 1;
        continue;
      }
      const p: Vec3 = [x + offset[0], height + offset[1], z + offset[2]];
      const o: Vec3 = [p[0], p[1] + SHADOW_RAY_OFFSET, p[2]];
      const seen = lamps.map((lamp) => {
        if (!caster) return lamp;
        const keep = lamp.sources.map((src) => {
          const d: Vec3 = [src[0] - o[0], src[1] - o[1], src[2] - o[2]];
          const dist = Math.hypot(d[0], d[1], d[2]);
          return !(dist > 0) || !caster.anyHit(o, [d[0] / dist, d[1] / dist, d[2] / dist], dist * (1 - 1e-6));
        });
        return { ...lamp, sources: lamp.sources.filter((_, s) => keep[s]), sides: lamp.sides.filter((_, s) => keep[s]) };
      });
      const e = directAtPoint(seen, p, [0, 1, 0]);
      let indirect = 0;
      // The floor (or what stands on it) under the point: its indirect light from the atlas.
      const hit = caster && light ? caster.closestHit(p, down, height + 1) : null;
      if (hit && light) {
        const t = Math.min(light.atlas.height - 1, Math.floor(hit.atlasUv[1] * light.atlas.height)) * light.atlas.width + Math.min(light.atlas.width - 1, Math.floor(hit.atlasUv[0] * light.atlas.width));
        indirect = Math.max(0, Y(light.total, t) - Y(light.direct, t));
      }
      values[k * nx + i] = LUMINANCE_WEIGHTS[0] * e[0] + LUMINANCE_WEIGHTS[1] * e[1] + LUMINANCE_WEIGHTS[2] * e[2] + indirect;
    }
  }
  const taken = values.filter((_, k) => covered[k] === 0);
  return { ...statsOf(taken), values, covered, nx, nz };
}
