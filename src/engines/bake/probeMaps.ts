import { SURFACE_NAMES, type Rgb, type SurfaceName, type Vec3 } from '../../core/model/lightingScene';
import { LUMINANCE_WEIGHTS, type BakedMaps } from './bakedMaps';
import { SURFACE_FRAMES, type SurfaceLayout } from './surfaceLayout';
import { directAtPoint } from './directAtPoint';
import { scenePointSources, type LampSources } from './scenePointSources';
import type { BakeScene } from './bakeScene';
import { resolveBakeSettings, type BakeSettings } from './bakeSettings';

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

/** Bilinear lookup between texel centres (clamped at the borders) of an RGB map at surface coordinates (u, v) in metres. */
export function bilinearRgb(layout: SurfaceLayout, rgb: Float32Array, u: number, v: number): Rgb {
  const fx = Math.min(layout.width - 1, Math.max(0, (u / layout.lengthU) * layout.width - 0.5));
  const fy = Math.min(layout.height - 1, Math.max(0, (v / layout.lengthV) * layout.height - 0.5));
  const x0 = Math.floor(fx);
  const y0 = Math.floor(fy);
  const x1 = Math.min(layout.width - 1, x0 + 1);
  const y1 = Math.min(layout.height - 1, y0 + 1);
  const tx = fx - x0;
  const ty = fy - y0;
  const out: Rgb = [0, 0, 0];
  for (let c = 0; c < 3; c++) {
    const a = rgb[(y0 * layout.width + x0) * 3 + c] * (1 - tx) + rgb[(y0 * layout.width + x1) * 3 + c] * tx;
    const b = rgb[(y1 * layout.width + x0) * 3 + c] * (1 - tx) + rgb[(y1 * layout.width + x1) * 3 + c] * tx;
    out[c] = a * (1 - ty) + b * ty;
  }
  return out;
}

/** Bilinear lookup of an RGB map, as lux (photometric Y; Y is linear in RGB, so interpolating first is exact). */
export function bilinearLux(layout: SurfaceLayout, rgb: Float32Array, u: number, v: number): number {
  const [r, g, b] = bilinearRgb(layout, rgb, u, v);
  return LUMINANCE_WEIGHTS[0] * r + LUMINANCE_WEIGHTS[1] * g + LUMINANCE_WEIGHTS[2] * b;
}

export interface ProbeValue {
  surface: SurfaceName;
  direct: number;
  indirect: number;
  total: number;
}

/** Illuminance (lux) at a point on a surface of the baked room: nearest surface, bilinear in its maps. */
export function probeMaps(maps: BakedMaps, room: { width: number; height: number; depth: number }, point: Vec3): ProbeValue {
  const { surface } = nearestSurface(room, point);
  const m = maps[surface];
  const u = point[m.layout.uAxisIndex];
  const v = point[m.layout.vAxisIndex];
  return {
    surface,
    direct: bilinearLux(m.layout, m.direct, u, v),
    indirect: bilinearLux(m.layout, m.indirect, u, v),
    total: bilinearLux(m.layout, m.total, u, v),
  };
}

/**
 * Illuminance at a point on a surface with the direct part evaluated exactly at
 * the point (directAtPoint: the same point sources as the bake, on the CPU) and
 * only the indirect part read from the maps (bilinear). What `luxbox probe`
 * prints: near a hot spot direct light varies by orders of magnitude within a
 * texel, so a map lookup of it is wrong at any texel size; the indirect light is
 * smooth there.
 */
export function probeExact(
  maps: BakedMaps,
  lamps: readonly LampSources[],
  room: { width: number; height: number; depth: number },
  point: Vec3,
): ProbeValue {
  const { surface } = nearestSurface(room, point);
  const m = maps[surface];
  const u = point[m.layout.uAxisIndex];
  const v = point[m.layout.vAxisIndex];
  // On the surface's plane (probe points may lie up to 1 cm off it).
  const p: Vec3 = [point[0], point[1], point[2]];
  p[m.layout.normalAxisIndex] = m.layout.origin[m.layout.normalAxisIndex];
  p[m.layout.uAxisIndex] = Math.min(m.layout.lengthU, Math.max(0, u));
  p[m.layout.vAxisIndex] = Math.min(m.layout.lengthV, Math.max(0, v));
  const d = directAtPoint(lamps, p, m.layout.normal);
  const direct = LUMINANCE_WEIGHTS[0] * d[0] + LUMINANCE_WEIGHTS[1] * d[1] + LUMINANCE_WEIGHTS[2] * d[2];
  const indirect = bilinearLux(m.layout, m.indirect, u, v);
  return { surface, direct, indirect, total: direct + indirect };
}

/** probeExact at many points of a baked scene (the point sources follow the same settings as the bake). */
export function probeScene(scene: BakeScene, maps: BakedMaps, settings: Partial<BakeSettings>, points: readonly Vec3[]): ProbeValue[] {
  const lamps = scenePointSources(scene, resolveBakeSettings(settings));
  return points.map((p) => probeExact(maps, lamps, scene.room, p));
}
