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
import { enclosureBox, encloseShapedRoom } from '../bake/shapedRoom/encloseShapedRoom';
import type { LitMaps } from '../relight/relightMaps';
import { statsOf, type IlluminanceStats } from './lightStats';

/** Shadow rays start this far above the plane (metres), as in workPlaneStats. */
const SHADOW_RAY_OFFSET = 1e-4;

const Y = (m: ArrayLike<number>, t: number) => LUMINANCE_WEIGHTS[0] * m[3 * t] + LUMINANCE_WEIGHTS[1] * m[3 * t + 1] + LUMINANCE_WEIGHTS[2] * m[3 * t + 2];

/** The shaped room's work-plane grid: its points in bake coordinates, those left out, and the atlas texel under each point (−1: none). */
export interface ShapedWorkPlaneGrid {
  height: number;
  nx: number;
  nz: number;
  /** 1 where the point lies outside the outline or above the ceiling there, row-major. */
  covered: Uint8Array;
  /** Per point its position in the enclosure's (bake) coordinates, 3 floats. */
  points: Float32Array;
  /** Per point the atlas texel a ray straight down meets (the floor or what stands on it), or −1. */
  floorTexel: Int32Array;
  caster: ReturnType<typeof createObjectRayCaster> | null;
}

/** The grid at `height`, `spacing` apart, over the outline's bounding box; `objects`: the enclosure's prepared objects (the room's surfaces first). */
export function shapedWorkPlaneGrid(scene: BakeScene, height: number, spacing: number, objects: PreparedObjects | null): ShapedWorkPlaneGrid {
  const shape = scene.room.shape!;
  const offset = enclosureBox(shape).offset;
  const caster = objects && objects.triangleCount > 0 ? createObjectRayCaster(objects) : null;
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const [x0, z0] = [Math.min(...xs), Math.min(...zs)];
  const [width, depth] = [Math.max(...xs) - x0, Math.max(...zs) - z0];
  const nx = Math.max(1, Math.round(width / spacing));
  const nz = Math.max(1, Math.round(depth / spacing));
  const covered = new Uint8Array(nx * nz);
  const points = new Float32Array(nx * nz * 3);
  const floorTexel = new Int32Array(nx * nz).fill(-1);
  const down: Vec3 = [0, -1, 0];
  const atlas = objects?.atlas;
  for (let k = 0; k < nz; k++) {
    for (let i = 0; i < nx; i++) {
      const x = x0 + ((i + 0.5) / nx) * width;
      const z = z0 + ((k + 0.5) / nz) * depth;
      const n = k * nx + i;
      if (!pointInsideRoom(shape, [x, height, z], 0)) {
        covered[n] = 1;
        continue;
      }
      const p: Vec3 = [x + offset[0], height + offset[1], z + offset[2]];
      points.set(p, 3 * n);
      const hit = caster && atlas ? caster.closestHit(p, down, height + 1) : null;
      if (hit && atlas) floorTexel[n] = Math.min(atlas.height - 1, Math.floor(hit.atlasUv[1] * atlas.height)) * atlas.width + Math.min(atlas.width - 1, Math.floor(hit.atlasUv[0] * atlas.width));
    }
  }
  return { height, nx, nz, covered, points, floorTexel, caster };
}

/**
 * RGB direct lux at each point of the grid (3 floats a point, 0 where covered) from `luminaires`,
 * each point source only where a shadow ray reaches it. `enclosed`: the luminaires are in the
 * enclosure's coordinates already (the relight engine's bases, baked in the enclosure), else in the
 * room's (a scene as the planner hands it over).
 */
export function shapedWorkPlaneDirect(scene: BakeScene, grid: ShapedWorkPlaneGrid, luminaires: readonly BakeScene['luminaires'][number][], enclosed: boolean, settings: Partial<BakeSettings> = {}): Float32Array {
  const inEnclosure = enclosed ? { ...encloseShapedRoom({ ...scene, luminaires: [] }), luminaires: [...luminaires] } : encloseShapedRoom({ ...scene, luminaires: [...luminaires] });
  const lamps = scenePointSources(inEnclosure, resolveBakeSettings(settings));
  const { caster } = grid;
  const out = new Float32Array(grid.nx * grid.nz * 3);
  for (let n = 0; n < grid.nx * grid.nz; n++) {
    if (grid.covered[n]) continue;
    const p: Vec3 = [grid.points[3 * n], grid.points[3 * n + 1], grid.points[3 * n + 2]];
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
    out.set(directAtPoint(seen, p, [0, 1, 0]), 3 * n);
  }
  return out;
}

/** `objects`: the enclosure's prepared objects (the room's surfaces first), as the baker laid out the atlas `lit` holds. */
export function shapedWorkPlaneStats(
  scene: BakeScene,
  lit: LitMaps,
  height: number,
  spacing: number,
  settings: Partial<BakeSettings>,
  objects: PreparedObjects | null,
): IlluminanceStats & { values: Float32Array; covered: Uint8Array; nx: number; nz: number } {
  const grid = shapedWorkPlaneGrid(scene, height, spacing, objects);
  const direct = shapedWorkPlaneDirect(scene, grid, scene.luminaires, false, settings);
  const light = lit.maps.objects;
  const { nx, nz, covered } = grid;
  const values = new Float32Array(nx * nz);
  for (let n = 0; n < nx * nz; n++) {
    if (covered[n]) continue;
    const e = [direct[3 * n], direct[3 * n + 1], direct[3 * n + 2]];
    // The floor (or what stands on it) under the point: its indirect light from the atlas.
    const t = grid.floorTexel[n];
    const indirect = t >= 0 && light ? Math.max(0, Y(light.total, t) - Y(light.direct, t)) : 0;
    values[n] = LUMINANCE_WEIGHTS[0] * e[0] + LUMINANCE_WEIGHTS[1] * e[1] + LUMINANCE_WEIGHTS[2] * e[2] + indirect;
  }
  const taken = values.filter((_, k) => covered[k] === 0);
  return { ...statsOf(taken), values, covered, nx, nz };
}
