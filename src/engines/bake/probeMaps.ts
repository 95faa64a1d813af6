import type { SurfaceName, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS, type BakedMaps } from './bakedMaps';
import { bilinearLux } from './bilinearMap';
import { nearestSurface } from './nearestSurface';
import { directAtPoint } from './directAtPoint';
import { scenePointSources, type LampSources } from './scenePointSources';
import type { BakeScene } from './bakeScene';
import { resolveBakeSettings, type BakeSettings } from './bakeSettings';
import { SURFACE_OFFSET } from '../../../shaders/objectTracing.glsl';
import { createObjectRayCaster } from './objects/createObjectRayCaster';
import { prepareObjects } from './objects/prepareObjects';

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
export function probeExact(maps: BakedMaps, lamps: readonly LampSources[], room: { width: number; height: number; depth: number }, point: Vec3, visible?: (p: Vec3, n: Vec3, source: Vec3) => boolean): ProbeValue {
  const { surface } = nearestSurface(room, point);
  const m = maps[surface];
  const u = point[m.layout.uAxisIndex];
  const v = point[m.layout.vAxisIndex];
  // On the surface's plane (probe points may lie up to 1 cm off it).
  const p: Vec3 = [point[0], point[1], point[2]];
  p[m.layout.normalAxisIndex] = m.layout.origin[m.layout.normalAxisIndex];
  p[m.layout.uAxisIndex] = Math.min(m.layout.lengthU, Math.max(0, u));
  p[m.layout.vAxisIndex] = Math.min(m.layout.lengthV, Math.max(0, v));
  const d = directAtPoint(lamps, p, m.layout.normal, visible);
  const direct = LUMINANCE_WEIGHTS[0] * d[0] + LUMINANCE_WEIGHTS[1] * d[1] + LUMINANCE_WEIGHTS[2] * d[2];
  const indirect = bilinearLux(m.layout, m.indirect, u, v);
  return { surface, direct, indirect, total: direct + indirect };
}

/**
 * probeExact at many points of a baked scene (the point sources follow the same settings as the
 * bake). With objects, direct light is shadow-tested on the CPU exactly as the direct pass does it
 * (objectTracing.glsl.ts: origin 0.1 mm off the surface, ray stopped 1e-4 of its length short of
 * the source), through the same BVH (objects/createObjectRayCaster.ts).
 */
export function probeScene(scene: BakeScene, maps: BakedMaps, settings: Partial<BakeSettings>, points: readonly Vec3[]): ProbeValue[] {
  const resolved = resolveBakeSettings(settings);
  const lamps = scenePointSources(scene, resolved);
  const visible = scene.objects && scene.objects.length > 0 ? objectVisibility(scene, resolved) : undefined;
  return points.map((p) => probeExact(maps, lamps, scene.room, p, visible));
}

function objectVisibility(scene: BakeScene, settings: BakeSettings): (p: Vec3, n: Vec3, source: Vec3) => boolean {
  const caster = createObjectRayCaster(prepareObjects(scene.objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize }));
  return (p, n, source) => {
    const o: Vec3 = [p[0] + n[0] * SURFACE_OFFSET, p[1] + n[1] * SURFACE_OFFSET, p[2] + n[2] * SURFACE_OFFSET];
    const d: Vec3 = [source[0] - o[0], source[1] - o[1], source[2] - o[2]];
    const dist = Math.hypot(d[0], d[1], d[2]);
    if (dist < 1e-6) return true;
    return !caster.anyHit(o, [d[0] / dist, d[1] / dist, d[2] / dist], dist * (1 - 1e-4));
  };
}
