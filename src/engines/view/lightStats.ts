import type { BakeScene } from '../bake/bakeScene';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { bilinearRgb } from '../bake/bilinearMap';
import { resolveBakeSettings, type BakeSettings } from '../bake/bakeSettings';
import { directAtPoint } from '../bake/directAtPoint';
import { scenePointSources } from '../bake/scenePointSources';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { createObjectRayCaster } from '../bake/objects/createObjectRayCaster';
import type { PreparedObjects } from '../bake/objects/preparedObjects';
import type { SurfaceLayout } from '../bake/surfaceLayout';
import { objectRenderGeometry } from './objectRenderGeometry';
import { roomSurfaceStats } from './roomSurfaceStats';
import { shapedWorkPlaneStats } from './shapedWorkPlaneStats';

/** Shadow rays toward the lamps start this far above the work plane (metres): clear of a table top lying in it. */
const SHADOW_RAY_OFFSET = 1e-4;

/** The numbers a lighting planner asks for first (EN 12464-1 vocabulary): lux and uniformity U0 = Emin/Ē. */
export interface IlluminanceStats {
  avg: number;
  min: number;
  max: number;
  /** Emin / Ē (0 when Ē is 0). */
  u0: number;
  /** Grid points the numbers are taken over. */
  points: number;
}

const Y = (r: number, g: number, b: number) => LUMINANCE_WEIGHTS[0] * r + LUMINANCE_WEIGHTS[1] * g + LUMINANCE_WEIGHTS[2] * b;

/** Statistics of illuminance values (lux) on an equal-area grid. */
export function statsOf(values: ArrayLike<number>): IlluminanceStats {
  let sum = 0;
  let min = Infinity;
  let max = -Infinity;
  for (let i = 0; i < values.length; i++) {
    const v = values[i];
    sum += v;
    if (v < min) min = v;
    if (v > max) max = v;
  }
  const n = values.length;
  if (n === 0) return { avg: 0, min: 0, max: 0, u0: 0, points: 0 };
  const avg = sum / n;
  return { avg, min, max, u0: avg > 0 ? min / avg : 0, points: n };
}

/**
 * An object stands on the floor when its lowest point is at most this far above it (metres): a
 * sofa, a table on its legs, a bed. Its plan silhouette hides floor; a shelf or a picture hung on
 * a wall does not (the floor under it is in plain view).
 */
export const FLOOR_CONTACT_M = 0.01;

/** A regular grid of points on a horizontal plane: cell (i, j) has its centre at (x0 + (i + 0.5)·dx, z0 + (j + 0.5)·dz). */
interface PlanGrid {
  x0: number;
  z0: number;
  dx: number;
  dz: number;
  nx: number;
  nz: number;
}

/**
 * 1 for each grid cell whose centre lies inside the plan silhouette (the union of the triangles
 * projected onto the floor, as the plan draws objects) of an object standing on the floor
 * (FLOOR_CONTACT_M); row-major. `above`: only faces lying wholly higher than this (metres) count,
 * so a plane is covered where furniture rises through it, not where it only passes over a low
 * table; null: every face. The triangles come from the prepared objects the baker lit
 * (objectRenderGeometry). Cost: one pass over each standing object's triangles with a
 * point-in-triangle test per cell of its plan bounding box.
 */
function gridUnderObjects(grid: PlanGrid, objects: PreparedObjects | null, above: number | null): Uint8Array {
  const covered = new Uint8Array(grid.nx * grid.nz);
  if (!objects || objects.triangleCount === 0) return covered;
  const standing = objects.objects.map((o) => o.bounds.min[1] <= FLOOR_CONTACT_M);
  if (!standing.some(Boolean)) return covered;
  const geometry = objectRenderGeometry(objects);
  const p = geometry.positions;
  const { x0, z0, dx, dz } = grid;
  for (let t = 0; t < geometry.triangleCount; t++) {
    if (!standing[geometry.objectOfTriangle[t]]) continue;
    const o = t * 9;
    if (above !== null && !(Math.min(p[o + 1], p[o + 4], p[o + 7]) > above)) continue;
    const ax = p[o],
      az = p[o + 2],
      bx = p[o + 3],
      bz = p[o + 5],
      cx = p[o + 6],
      cz = p[o + 8];
    const area = (bx - ax) * (cz - az) - (bz - az) * (cx - ax);
    if (Math.abs(area) < 1e-12) continue; // a side face, seen edge-on from above: its neighbours cover the plan
    const i0 = Math.max(0, Math.ceil((Math.min(ax, bx, cx) - x0) / dx - 0.5));
    const i1 = Math.min(grid.nx - 1, Math.floor((Math.max(ax, bx, cx) - x0) / dx - 0.5));
    const j0 = Math.max(0, Math.ceil((Math.min(az, bz, cz) - z0) / dz - 0.5));
    const j1 = Math.min(grid.nz - 1, Math.floor((Math.max(az, bz, cz) - z0) / dz - 0.5));
    const sign = Math.sign(area);
    for (let j = j0; j <= j1; j++) {
      const z = z0 + (j + 0.5) * dz;
      for (let i = i0; i <= i1; i++) {
        const x = x0 + (i + 0.5) * dx;
        // Inside (edges included) when the three edge functions share the triangle's orientation.
        const w0 = ((bx - ax) * (z - az) - (bz - az) * (x - ax)) * sign;
        const w1 = ((cx - bx) * (z - bz) - (cz - bz) * (x - bx)) * sign;
        const w2 = ((ax - cx) * (z - cz) - (az - cz) * (x - cx)) * sign;
        if (w0 >= 0 && w1 >= 0 && w2 >= 0) covered[j * grid.nx + i] = 1;
      }
    }
  }
  return covered;
}

/**
 * Which floor texels lie under furniture: 1 where the texel's centre is inside the plan silhouette
 * of an object that stands on the floor (FLOOR_CONTACT_M), else 0; row-major like the floor map.
 */
export function floorUnderObjects(floor: SurfaceLayout, objects: PreparedObjects | null): Uint8Array {
  const dx = floor.lengthU / floor.width;
  const dz = floor.lengthV / floor.height;
  return gridUnderObjects({ x0: floor.origin[floor.uAxisIndex], z0: floor.origin[floor.vAxisIndex], dx, dz, nx: floor.width, nz: floor.height }, objects, null);
}

/**
 * Which points of a work plane at `height` lie inside furniture: 1 where the point's plan position
 * is under a face of a standing object lying wholly above height + FLOOR_CONTACT_M (the object
 * rises through the plane there: a shelf, a sofa's back, a person), else 0. A table whose top is
 * the work plane, or a coffee table below it, covers nothing: the plane over it is free. The same
 * silhouette rule as the floor (floorUnderObjects), applied to what reaches above the plane.
 */
export function workPlaneUnderObjects(room: { width: number; depth: number }, nx: number, nz: number, height: number, objects: PreparedObjects | null): Uint8Array {
  return gridUnderObjects({ x0: 0, z0: 0, dx: room.width / nx, dz: room.depth / nz, nx, nz }, objects, height + FLOOR_CONTACT_M);
}

/**
 * Floor statistics from the relit floor map: texel centres are an equal-area grid. With the
 * scene's prepared objects, the texels under furniture that stands on the floor are left out
 * (floorUnderObjects): the floor a person sees, as EN 12464-1 task and surrounding areas leave out
 * the area furniture occupies. `points` counts the texels taken.
 */
export function floorStats(lit: LitMaps, objects: PreparedObjects | null = null): IlluminanceStats {
  // A shaped room's floor is in the atlas (engines/bake/shapedRoom): its texels there, the box's floor is a sink.
  if (lit.layouts.floor.sink && objects && lit.maps.objects) return roomSurfaceStats(objects, lit.maps.objects.total, lit.maps.objects.atlas).find((s) => s.surface === 'floor') ?? statsOf([]);
  const rgb = lit.maps.floor.total;
  const covered = floorUnderObjects(lit.layouts.floor, objects);
  const lux: number[] = [];
  for (let i = 0; i < covered.length; i++) if (!covered[i]) lux.push(Y(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2]));
  return statsOf(lux);
}

/**
 * The direct illuminance (RGB lux, 3 floats per point, row-major) of `luminaires` on the box room's
 * work-plane grid of nx × nz cell centres at `height`: E = Σ I(γ,C)·cosθ/d² from the baker's point
 * sources (directAtPoint, CIE 171:2006 §5.2), each source counted only where a shadow ray from the
 * point reaches it past every object. Light adds, so the sum of this over a partition of the
 * luminaires (the relight's groups, workPlaneBases.ts) is this over all of them.
 */
export function workPlaneDirect(scene: BakeScene, luminaires: readonly BakeScene['luminaires'][number][], height: number, nx: number, nz: number, settings: Partial<BakeSettings> = {}, objects: PreparedObjects | null = null): Float32Array {
  const { width, depth } = scene.room;
  const lamps = scenePointSources({ ...scene, luminaires: [...luminaires] }, resolveBakeSettings(settings));
  const caster = objects && objects.triangleCount > 0 ? createObjectRayCaster(objects) : null;
  /** The lamps with only the point sources a point of the plane sees. */
  const visibleFrom = (p: Vec3): typeof lamps => {
    if (!caster) return lamps;
    const o: Vec3 = [p[0], p[1] + SHADOW_RAY_OFFSET, p[2]];
    return lamps.map((lamp) => {
      const keep = lamp.sources.map((src) => {
        const d: Vec3 = [src[0] - o[0], src[1] - o[1], src[2] - o[2]];
        const dist = Math.hypot(d[0], d[1], d[2]);
        return !(dist > 0) || !caster.anyHit(o, [d[0] / dist, d[1] / dist, d[2] / dist], dist * (1 - 1e-6));
      });
      return { ...lamp, sources: lamp.sources.filter((_, k) => keep[k]), sides: lamp.sides.filter((_, k) => keep[k]) };
    });
  };
  const out = new Float32Array(nx * nz * 3);
  const up: Vec3 = [0, 1, 0];
  for (let k = 0; k < nz; k++) {
    for (let i = 0; i < nx; i++) {
      const x = ((i + 0.5) / nx) * width;
      const z = ((k + 0.5) / nz) * depth;
      out.set(directAtPoint(visibleFrom([x, height, z]), [x, height, z], up), (k * nx + i) * 3);
    }
  }
  return out;
}

/**
 * Illuminance on a horizontal work plane at `height` metres, on a grid of
 * `spacing` metres (cell centres) over the room.
 *
 * Method (docs/viewer.md): direct light exactly, E = Σ I(γ,C)·cosθ/d² from the
 * same point sources the baker uses (directAtPoint, CIE 171:2006 §5.2);
 * indirect light estimated by the floor's indirect illuminance at the same
 * plan point (the up-facing plane sees the ceiling and the walls above it, the
 * floor the same plus the wall band below the plane: nearly the same view of
 * the bright surfaces, so the estimate errs low by the band's small share).
 * Luminaires below the plane light it from underneath and are skipped by the
 * cosine test, as they should be. With `objects` (the scene's, prepared as the
 * baker lays them out) each point source counts only where a shadow ray from
 * the grid point reaches it past every object (the CPU ray caster over the
 * baker's BVH): the plane under a shelf board or inside a sofa is shaded; and the
 * statistics leave out the points inside furniture standing on the floor
 * (workPlaneUnderObjects), as the floor's leave out what furniture occupies
 * (EN 12464-1). `values` keeps every point (0 where no light reaches); `covered`
 * marks the points left out and `points` counts those taken.
 */
export function workPlaneStats(
  scene: BakeScene,
  lit: LitMaps,
  height: number,
  spacing = 0.1,
  settings: Partial<BakeSettings> = {},
  objects: PreparedObjects | null = null,
): IlluminanceStats & { values: Float32Array; covered: Uint8Array; nx: number; nz: number } {
  // A room of any shape: the grid over its outline, shadows of its own corners, indirect light from the atlas floor.
  if (scene.room.shape) return shapedWorkPlaneStats(scene, lit, height, spacing, settings, objects);
  const { width, depth } = scene.room;
  const nx = Math.max(1, Math.round(width / spacing));
  const nz = Math.max(1, Math.round(depth / spacing));
  const direct = workPlaneDirect(scene, scene.luminaires, height, nx, nz, settings, objects);
  const values = new Float32Array(nx * nz);
  const floor = lit.layouts.floor;
  const floorDirect = lit.maps.floor.direct;
  const total = lit.maps.floor.total;
  for (let k = 0; k < nz; k++) {
    for (let i = 0; i < nx; i++) {
      const x = ((i + 0.5) / nx) * width;
      const z = ((k + 0.5) / nz) * depth;
      const p = (k * nx + i) * 3;
      const t = bilinearRgb(floor, total, x, z);
      const d = bilinearRgb(floor, floorDirect, x, z);
      values[k * nx + i] = Y(direct[p], direct[p + 1], direct[p + 2]) + Math.max(0, Y(t[0] - d[0], t[1] - d[1], t[2] - d[2]));
    }
  }
  const covered = workPlaneUnderObjects(scene.room, nx, nz, height, objects);
  const taken = values.filter((_, k) => covered[k] === 0);
  return { ...statsOf(taken), values, covered, nx, nz };
}
