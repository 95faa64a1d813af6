/**
 * `luxbox probe` in a room of any shape (issue 29; docs/scene-format.md, "Probe points"). The bake
 * of such a room is the bake of its enclosure (src/engines/bake/shapedRoom/encloseShapedRoom.ts:
 * the room's surfaces are charts of the objects' atlas, bake coordinates = world + offset), so the
 * probe is the box room's probe (createProbe.ts) on the enclosed scene, with the points moved into
 * bake coordinates:
 * - a point [x, y, z] on a room surface (roomSurfaceAt, within `tolerance`) is put on that surface's
 *   plane; direct light is exact there (the room's own surfaces occlude, as they do in the bake), the
 *   indirect light is bilinear in the atlas map of that surface's chart;
 * - a point with a normal is createProbe's `atPlane`: direct with occlusion, indirect gathered over
 *   the baked maps (rays that leave through an opening reach the enclosure's black sinks: no light).
 * With daylight (windows and a sky, docs/daylight.md), the direct light adds the sky, the ground
 * and the sun through the windows exactly at the point (daylightAtPoint.ts, the baker's own
 * per-texel computation, sight lines through the room's BVH where they can be blocked); the
 * indirect daylight is in the baked maps.
 */
import { InputError } from '../../core/inputError';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';
import { pointInsideRoom } from '../../core/room/ceilingHeightAt';
import type { Room } from '../../core/room/normaliseRoom';
import { roomSurfaceAt } from '../../core/room/roomSurfaceAt';
import { roomSurfaces } from '../../core/room/roomSurfaces';
import type { BakedMaps } from '../../engines/bake/bakedMaps';
import type { BakeScene } from '../../engines/bake/bakeScene';
import { resolveBakeSettings, type BakeSettings } from '../../engines/bake/bakeSettings';
import { daylightPointContext } from '../../engines/bake/daylight/daylightAtlasDirect';
import { skyDaylightAt, sunDaylightAt } from '../../engines/bake/daylight/daylightAtPoint';
import { daylightBakeInput } from '../../engines/bake/daylight/daylightBakeInput';
import { prepareObjectsCached } from '../../engines/bake/objects/prepareObjectsCached';
import { encloseShapedRoom } from '../../engines/bake/shapedRoom/encloseShapedRoom';
import { createProbe, type ProbeOptions } from './createProbe';

export interface ShapedProbeResult {
  /** The room surface's id (`floor`, `slope-0`, `wall-3`, …) of a surface point; absent for a point with a normal. */
  surface?: string;
  direct: number;
  indirect: number;
  total: number;
}

export interface ShapedProbePoint {
  point: Vec3;
  normal?: Vec3;
}

/** Check every point against the room before anything is baked: a refusal names the point (`points[i]: …`) and why. */
export function checkShapedProbePoints(room: Room, points: readonly ShapedProbePoint[], tolerance: number, source: string): void {
  const surfaces = roomSurfaces(room);
  points.forEach(({ point, normal }, i) => {
    if (normal) {
      if (!pointInsideRoom(room, point, tolerance)) throw new InputError(`${source}: points[${i}]: [${point.join(', ')}] is outside the room (its outline, floor, ceiling and slopes)`);
      return;
    }
    const at = roomSurfaceAt(room, point, tolerance, surfaces);
    if (at.surface) return;
    if (at.opening) throw new InputError(`${source}: points[${i}]: [${point.join(', ')}] lies in opening ${at.opening.index} of ${at.opening.surface.id}, where the room has no surface`);
    const near = at.nearest ? ` (nearest: ${at.nearest.surface.id}, ${at.nearest.distance.toPrecision(3)} m away)` : '';
    throw new InputError(`${source}: points[${i}]: [${point.join(', ')}] is on no surface of the room${near}; probe points must lie within ${tolerance} m of a surface`);
  });
}

/** Illuminance at checked points (checkShapedProbePoints), world coordinates; `maps` are the bake of `scene` (createBaker encloses it) with the same settings. */
export function probeShapedRoom(scene: BakeScene, maps: BakedMaps, settings: Partial<BakeSettings>, points: readonly ShapedProbePoint[], tolerance: number): ShapedProbeResult[] {
  const room = scene.room.shape;
  if (!room) throw new Error('probeShapedRoom: the scene has no room of any shape');
  const enclosed = encloseShapedRoom(scene);
  const offset = enclosed.room.enclosure!.offset;
  const probe = createProbe(enclosed, maps, settings, daylightProbeOptions(scene, enclosed, settings));
  const surfaces = roomSurfaces(room);
  const move = (p: readonly number[]): Vec3 => [p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]];
  return points.map(({ point, normal }) => {
    if (normal) return probe.atPlane(move(point), normal);
    const at = roomSurfaceAt(room, point, tolerance, surfaces);
    if (!at.surface) throw new Error(`probeShapedRoom: [${point.join(', ')}] is on no surface (check the points first)`);
    const { surface } = at;
    const n = surface.inward;
    // On the surface's plane (probe points may lie up to `tolerance` off it).
    const h = (point[0] - surface.frame.origin[0]) * n[0] + (point[1] - surface.frame.origin[1]) * n[1] + (point[2] - surface.frame.origin[2]) * n[2];
    const onPlane = move([point[0] - h * n[0], point[1] - h * n[1], point[2] - h * n[2]]);
    return { surface: surface.id, ...probe.atAtlasFace(onPlane, [n[0], n[1], n[2]]) };
  });
}

/** The daylight's direct light at a point of the enclosed scene (bake coordinates), when the scene bakes daylight. */
function daylightProbeOptions(scene: BakeScene, enclosed: BakeScene, settingsIn: Partial<BakeSettings>): ProbeOptions {
  const day = daylightBakeInput(scene, enclosed);
  if (!day) return {};
  const settings = resolveBakeSettings(settingsIn);
  const prepared = prepareObjectsCached(enclosed.objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
  const ctx = daylightPointContext(prepared, day.daylight, day.windows, day.needsRays);
  return { extraDirect: (p, n) => skyDaylightAt(ctx, p, n) + sunDaylightAt(ctx, p, n) };
}
