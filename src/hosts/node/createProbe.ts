import type { Rgb, SurfaceName, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS, type BakedMaps } from '../../engines/bake/bakedMaps';
import { toRgb, type BakeScene } from '../../engines/bake/bakeScene';
import { resolveBakeSettings, type BakeSettings } from '../../engines/bake/bakeSettings';
import { bilinearLux, bilinearRgb } from '../../engines/bake/bilinearMap';
import { directAtPoint } from '../../engines/bake/directAtPoint';
import { nearestSurface } from '../../engines/bake/nearestSurface';
import { createObjectRayCaster, type ObjectRayCaster } from '../../engines/bake/objects/createObjectRayCaster';
import { prepareObjects } from '../../engines/bake/objects/prepareObjects';
import { scenePointSources, type LampSources } from '../../engines/bake/scenePointSources';
import { mulberry32 } from '../../core/mulberry32';

/** Rays of the indirect gather at a point with a normal (a 64 × 64 stratified grid). */
export const PROBE_GATHER_RAYS = 4096;
/** Seed of the gather's jitter: the same numbers on every run and machine. */
export const PROBE_GATHER_SEED = 0x1ab0c5;
/** Shadow and gather rays start this far off the surface (metres), clear of its own triangles. */
const RAY_OFFSET = 1e-4;
/** A face under a probe point is looked for this far above and below the point (metres): the point lies on the face's plane. */
const FACE_SEARCH = 1e-3;

export interface ProbeResult {
  /** The room surface of a surface point; absent for a point with a normal. */
  surface?: SurfaceName;
  direct: number;
  indirect: number;
  total: number;
}

export interface Probe {
  /** A point on a room surface (within 1 cm): direct exactly at the point (objects occluding), indirect from the surface's maps. */
  atSurface(point: Vec3): ProbeResult;
  /** Illuminance on the plane through `point` with unit normal `normal`, anywhere in the room: direct with occlusion, indirect by a CPU gather over the baked maps. */
  atPlane(point: Vec3, normal: Vec3): ProbeResult;
  /**
   * A point on a face of the objects' atlas whose front has unit normal `normal` (a shaped room's
   * surface: createShapedRoomProbe.ts): direct exactly at the point (objects occluding), indirect
   * bilinear in the atlas's map at the chart texel under the point (found by a ray along −normal).
   */
  atAtlasFace(point: Vec3, normal: Vec3): ProbeResult;
}

export interface ProbeOptions {
  /**
   * Direct light of sources other than the luminaires at a point (lux, Y; bake coordinates): the
   * daylight through a shaped room's windows (createShapedRoomProbe.ts, daylightAtPoint.ts).
   */
  extraDirect?: (point: Vec3, normal: Vec3) => number;
}

/** What every part of a probe reads: the baked maps, the room's size, the lamps and the objects' ray caster. */
interface ProbeContext {
  scene: BakeScene;
  maps: BakedMaps;
  dims: Vec3;
  lamps: readonly LampSources[];
  caster: ObjectRayCaster | null;
  extraDirect: (point: Vec3, normal: Vec3) => number;
}

const lux = (rgb: Rgb): number => LUMINANCE_WEIGHTS[0] * rgb[0] + LUMINANCE_WEIGHTS[1] * rgb[1] + LUMINANCE_WEIGHTS[2] * rgb[2];
const offsetAlong = (p: Vec3, n: Vec3, d: number): Vec3 => [p[0] + n[0] * d, p[1] + n[1] * d, p[2] + n[2] * d];

/** The ray caster over the bake's objects, checked to be the maps' atlas; null in a room without objects. */
function objectCaster(scene: BakeScene, maps: BakedMaps, settings: BakeSettings): ObjectRayCaster | null {
  if (!scene.objects || scene.objects.length === 0) return null;
  // The bake prepared the same objects with the same settings (prepareBakeInputs): the atlas is the maps' atlas.
  const prepared = prepareObjects(scene.objects, { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
  const atlas = maps.objects?.atlas;
  if (!atlas || atlas.width !== prepared.atlas.width || atlas.height !== prepared.atlas.height) {
    throw new Error(`probe: the bake's object atlas (${atlas ? `${atlas.width}×${atlas.height}` : 'none'}) is not the one prepared here (${prepared.atlas.width}×${prepared.atlas.height})`);
  }
  return createObjectRayCaster(prepared);
}

/** The lamps with only the point sources that `p` sees (all of them in an empty room). */
function visibleLamps(ctx: ProbeContext, p: Vec3, n: Vec3): readonly LampSources[] {
  const caster = ctx.caster;
  if (!caster) return ctx.lamps;
  const o = offsetAlong(p, n, RAY_OFFSET);
  return ctx.lamps.map((lamp) => {
    const keep = lamp.sources.map((s) => {
      const d: Vec3 = [s[0] - o[0], s[1] - o[1], s[2] - o[2]];
      const dist = Math.hypot(d[0], d[1], d[2]);
      if (!(dist > 0)) return true;
      return !caster.anyHit(o, [d[0] / dist, d[1] / dist, d[2] / dist], dist * (1 - 1e-6));
    });
    return { ...lamp, sources: lamp.sources.filter((_, k) => keep[k]), sides: lamp.sides.filter((_, k) => keep[k]) };
  });
}

/** Direct light at p on the plane with normal n: the visible lamps' point sources plus the extra sources (daylight). */
function directAt(ctx: ProbeContext, p: Vec3, n: Vec3): number {
  return lux(directAtPoint(visibleLamps(ctx, p, n), p, n)) + ctx.extraDirect(p, n);
}

/** ρ·E_total (RGB) of the atlas texel a ray hit, or black on the back of a face. */
function leavingAtlas(maps: BakedMaps, hit: { frontFace: boolean; atlasUv: readonly number[] }): Rgb {
  if (!hit.frontFace) return [0, 0, 0];
  const m = maps.objects!;
  const i = Math.min(m.atlas.width - 1, Math.max(0, Math.floor(hit.atlasUv[0] * m.atlas.width)));
  const j = Math.min(m.atlas.height - 1, Math.max(0, Math.floor(hit.atlasUv[1] * m.atlas.height)));
  const k = j * m.atlas.width + i;
  return [0, 1, 2].map((c) => m.atlas.reflectance[4 * k + c] * m.total[3 * k + c]) as Rgb;
}

const BOX_SURFACES = [
  ['west', 'east'],
  ['floor', 'ceiling'],
  ['north', 'south'],
] as const;

/** ρ·E_total (RGB) of the surface a ray from `o` along `dir` meets first: an object's face, else a wall of the box. */
function leaving(ctx: ProbeContext, o: Vec3, dir: Vec3): Rgb {
  let tWall = Infinity;
  let axis = 0;
  for (let a = 0; a < 3; a++) {
    if (dir[a] === 0) continue;
    const t = ((dir[a] > 0 ? ctx.dims[a] : 0) - o[a]) / dir[a];
    if (t < tWall) [tWall, axis] = [Math.max(0, t), a];
  }
  const hit = ctx.caster?.closestHit(o, dir, tWall) ?? null;
  if (hit) return leavingAtlas(ctx.maps, hit);
  const surface: SurfaceName = BOX_SURFACES[axis][dir[axis] > 0 ? 1 : 0];
  const layout = ctx.maps[surface].layout;
  const q = [o[0] + dir[0] * tWall, o[1] + dir[1] * tWall, o[2] + dir[2] * tWall];
  const e = bilinearRgb(layout, ctx.maps[surface].total, q[layout.uAxisIndex], q[layout.vAxisIndex]);
  const rho = toRgb(ctx.scene.room.reflectance[surface]);
  return [rho[0] * e[0], rho[1] * e[1], rho[2] * e[2]];
}

/** Bilinear lux of the atlas's indirect map at the face under `p` (charts are two texels apart and their gutters dilated: no other chart enters). */
function atlasIndirect(ctx: ProbeContext, p: Vec3, n: Vec3): number {
  const m = ctx.maps.objects;
  const o = offsetAlong(p, n, FACE_SEARCH);
  const hit = ctx.caster?.closestHit(o, [-n[0], -n[1], -n[2]], 2 * FACE_SEARCH) ?? null;
  if (!m || !hit) throw new Error(`probe: no face of the objects' atlas under [${p.join(', ')}]`);
  const { width, height } = m.atlas;
  const x = Math.min(width - 1, Math.max(0, hit.atlasUv[0] * width - 0.5));
  const y = Math.min(height - 1, Math.max(0, hit.atlasUv[1] * height - 0.5));
  const i0 = Math.floor(x);
  const j0 = Math.floor(y);
  const [i1, j1] = [Math.min(width - 1, i0 + 1), Math.min(height - 1, j0 + 1)];
  const [fx, fy] = [x - i0, y - j0];
  const at = (i: number, j: number): number => {
    const k = 3 * (j * width + i);
    return lux([m.indirect[k], m.indirect[k + 1], m.indirect[k + 2]]);
  };
  return (1 - fy) * ((1 - fx) * at(i0, j0) + fx * at(i1, j0)) + fy * ((1 - fx) * at(i0, j1) + fx * at(i1, j1));
}

/**
 * Indirect light on the plane (p, n): cosine-weighted rays over a stratified grid, each taking
 * ρ·E_total of the first surface it meets (the estimator E = mean ρ·E_hit).
 */
function gatherIndirect(ctx: ProbeContext, p: Vec3, n: Vec3): number {
  // An orthonormal frame (t, b, n) (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017).
  const sign = n[2] >= 0 ? 1 : -1;
  const a = -1 / (sign + n[2]);
  const b = n[0] * n[1] * a;
  const t: Vec3 = [1 + sign * n[0] * n[0] * a, sign * b, -sign * n[0]];
  const bt: Vec3 = [b, sign + n[1] * n[1] * a, -n[1]];
  const o = offsetAlong(p, n, RAY_OFFSET);
  const random = mulberry32(PROBE_GATHER_SEED);
  const side = Math.round(Math.sqrt(PROBE_GATHER_RAYS));
  const sum: Rgb = [0, 0, 0];
  for (let s = 0; s < side * side; s++) {
    // Stratified in (u1, u2), then Malley's method: uniform on the disc, lifted to the hemisphere.
    const u1 = (Math.floor(s / side) + random()) / side;
    const u2 = ((s % side) + random()) / side;
    const r = Math.sqrt(u1);
    const phi = 2 * Math.PI * u2;
    const x = r * Math.cos(phi);
    const y = r * Math.sin(phi);
    const z = Math.sqrt(Math.max(0, 1 - u1));
    const dir: Vec3 = [x * t[0] + y * bt[0] + z * n[0], x * t[1] + y * bt[1] + z * n[1], x * t[2] + y * bt[2] + z * n[2]];
    const l = leaving(ctx, o, dir);
    sum[0] += l[0];
    sum[1] += l[1];
    sum[2] += l[2];
  }
  return lux([sum[0] / (side * side), sum[1] / (side * side), sum[2] / (side * side)]);
}

/** A point on a box surface: direct exactly on the surface's plane, indirect bilinear in its map. */
function atBoxSurface(ctx: ProbeContext, point: Vec3): ProbeResult {
  const { surface } = nearestSurface(ctx.scene.room, point);
  const m = ctx.maps[surface];
  const { uAxisIndex: ua, vAxisIndex: va, normalAxisIndex: na } = m.layout;
  // On the surface's plane (probe points may lie up to 1 cm off it), as probeExact does.
  const p: Vec3 = [point[0], point[1], point[2]];
  p[na] = m.layout.origin[na];
  p[ua] = Math.min(m.layout.lengthU, Math.max(0, point[ua]));
  p[va] = Math.min(m.layout.lengthV, Math.max(0, point[va]));
  const direct = directAt(ctx, p, m.layout.normal);
  const indirect = bilinearLux(m.layout, m.indirect, point[ua], point[va]);
  return { surface, direct, indirect, total: direct + indirect };
}

/**
 * `luxbox probe` after a bake (docs/scene-format.md, "Probe points"). Direct light is
 * directAtPoint's E = Σ I·cos/d² over the bake's point sources (CIE 171:2006 §5.2), each source
 * kept only if a shadow ray from the point reaches it past every object (the CPU twin of the GPU
 * BVH, createObjectRayCaster, over the same prepared objects as the bake), plus `extraDirect`
 * (daylight). Indirect light at a point with a normal is a gather: cosine-weighted rays (pdf
 * cos θ/π), each taking the light that leaves the first surface it meets, L = ρ·E_total/π, from
 * the baked total map of that wall or atlas texel (the back of an object's face is dark), so
 * E_indirect = π·mean(L) = mean(ρ·E_total) (Pharr, Jakob & Humphreys, Physically Based
 * Rendering, 4th ed., §13.6.3, cosine-weighted hemisphere sampling).
 */
export function createProbe(scene: BakeScene, maps: BakedMaps, settingsIn: Partial<BakeSettings>, options: ProbeOptions = {}): Probe {
  const settings = resolveBakeSettings(settingsIn);
  const room = scene.room;
  const ctx: ProbeContext = {
    scene,
    maps,
    dims: [room.width, room.height, room.depth],
    lamps: scenePointSources(scene, settings),
    caster: objectCaster(scene, maps, settings),
    extraDirect: options.extraDirect ?? (() => 0),
  };
  const result = (direct: number, indirect: number): ProbeResult => ({ direct, indirect, total: direct + indirect });
  return {
    atAtlasFace: (point, normal) => result(directAt(ctx, point, normal), atlasIndirect(ctx, point, normal)),
    atSurface: (point) => atBoxSurface(ctx, point),
    atPlane: (p, n) => result(directAt(ctx, p, n), gatherIndirect(ctx, p, n)),
  };
}
