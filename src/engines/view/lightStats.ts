import type { BakeScene } from '../bake/bakeScene';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { bilinearRgb } from '../bake/bilinearMap';
import { resolveBakeSettings, type BakeSettings } from '../bake/bakeSettings';
import { directAtPoint } from '../bake/directAtPoint';
import { scenePointSources } from '../bake/scenePointSources';
import type { Vec3 } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { createObjectRayCaster } from '../bake/objects/createObjectRayCaster';
import type { PreparedObjects } from '../bake/objects/preparedObjects';

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

/** Floor statistics from the relit floor map: texel centres are an equal-area grid. */
export function floorStats(lit: LitMaps): IlluminanceStats {
  const rgb = lit.maps.floor.total;
  const lux = new Float32Array(rgb.length / 3);
  for (let i = 0; i < lux.length; i++) lux[i] = Y(rgb[i * 3], rgb[i * 3 + 1], rgb[i * 3 + 2]);
  return statsOf(lux);
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
 * baker's BVH): the plane under a shelf board or inside a sofa is shaded.
 */
export function workPlaneStats(
  scene: BakeScene,
  lit: LitMaps,
  height: number,
  spacing = 0.1,
  settings: Partial<BakeSettings> = {},
  objects: PreparedObjects | null = null,
): IlluminanceStats & { values: Float32Array; nx: number; nz: number } {
  const { width, depth } = scene.room;
  const lamps = scenePointSources(scene, resolveBakeSettings(settings));
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
  const nx = Math.max(1, Math.round(width / spacing));
  const nz = Math.max(1, Math.round(depth / spacing));
  const values = new Float32Array(nx * nz);
  const floor = lit.layouts.floor;
  const direct = lit.maps.floor.direct;
  const total = lit.maps.floor.total;
  const up: Vec3 = [0, 1, 0];
  for (let k = 0; k < nz; k++) {
    for (let i = 0; i < nx; i++) {
      const x = ((i + 0.5) / nx) * width;
      const z = ((k + 0.5) / nz) * depth;
      const e = directAtPoint(visibleFrom([x, height, z]), [x, height, z], up);
      const t = bilinearRgb(floor, total, x, z);
      const d = bilinearRgb(floor, direct, x, z);
      values[k * nx + i] = Y(e[0], e[1], e[2]) + Math.max(0, Y(t[0] - d[0], t[1] - d[1], t[2] - d[2]));
    }
  }
  return { ...statsOf(values), values, nx, nz };
}
