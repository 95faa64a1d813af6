import type { OrientationSummary } from '../../core/mesh/orientMesh';
import { SURFACE_NAMES, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { luxOf, type BakedMaps } from '../../engines/bake/bakedMaps';
import type { BakeReport } from '../../engines/bake/createBaker';
import { texelArea } from '../../engines/bake/surfaceLayout';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { doubleSignedArea } from '../../core/room/planPolygon';
import { roomSurfaces } from '../../core/room/roomSurfaces';
import { ROOM_OBJECT_PREFIX } from '../../engines/bake/shapedRoom/roomSurfaceObjects';

/** A shaped room's surface ids, in atlas object order (the leading 'room:' objects of the report). */
export function roomSurfaceIds(report: BakeReport): string[] {
  const out: string[] = [];
  for (const o of report.objects ?? []) {
    if (!o.id.startsWith(ROOM_OBJECT_PREFIX)) break;
    out.push(o.id.slice(ROOM_OBJECT_PREFIX.length));
  }
  return out;
}

export interface SurfaceSummary {
  /** m² */
  area: number;
  /** lux (photometric Y of the RGB maps), over texel centres */
  min: number;
  avg: number;
  max: number;
  direct_avg: number;
  indirect_avg: number;
  texels: [number, number];
}

/** Per-surface statistics as report.json carries them (docs/scene-format.md, "Command-line contract"). */
export function summarizeSurfaces(maps: BakedMaps): Record<SurfaceName, SurfaceSummary> {
  const out = {} as Record<SurfaceName, SurfaceSummary>;
  for (const name of SURFACE_NAMES) {
    const m = maps[name];
    const total = luxOf(m.total);
    const direct = luxOf(m.direct);
    const indirect = luxOf(m.indirect);
    const mean = (a: Float32Array) => a.reduce((s, x) => s + x, 0) / a.length;
    let min = Infinity;
    let max = -Infinity;
    for (const x of total) {
      min = Math.min(min, x);
      max = Math.max(max, x);
    }
    out[name] = {
      area: texelArea(m.layout) * m.layout.width * m.layout.height,
      min,
      avg: mean(total),
      max,
      direct_avg: mean(direct),
      indirect_avg: mean(indirect),
      texels: [m.layout.width, m.layout.height],
    };
  }
  return out;
}

/** A shaped room's surface in report.json (issue 29): the numbers of its atlas texels, coverage-weighted. */
export interface RoomSurfaceSummary {
  /** m², openings left out (Σ coverage · texel²). */
  area: number;
  /** lux (photometric Y), over covered texels; avg weighted by coverage */
  min: number;
  avg: number;
  max: number;
  direct_avg: number;
  indirect_avg: number;
  /** Covered atlas texels. */
  texels: number;
}

/**
 * Per surface of a shaped room (its surfaces are the first objects of the atlas, ids
 * 'room:<surface>', engines/bake/shapedRoom), keyed by surface id ('floor', 'ceiling', 'slope-<i>',
 * 'wall-<i>'). The enclosure's six sink surfaces are no part of the room and are not reported.
 */
export function summarizeRoomSurfaces(maps: BakedMaps, ids: readonly string[]): Record<string, RoomSurfaceSummary> {
  const o = maps.objects;
  const out: Record<string, RoomSurfaceSummary> = {};
  if (!o) return out;
  const [total, direct, indirect] = [luxOf(o.total), luxOf(o.direct), luxOf(o.indirect)];
  const sums = ids.map(() => ({ w: 0, t: 0, d: 0, i: 0, n: 0, min: Infinity, max: -Infinity }));
  for (let k = 0; k < total.length; k++) {
    const w = o.atlas.position[4 * k + 3];
    const s = sums[Math.round(o.atlas.reflectance[4 * k + 3]) - 1];
    if (!(w > 0) || !s) continue;
    s.w += w;
    s.t += w * total[k];
    s.d += w * direct[k];
    s.i += w * indirect[k];
    s.n++;
    s.min = Math.min(s.min, total[k]);
    s.max = Math.max(s.max, total[k]);
  }
  ids.forEach((id, k) => {
    const s = sums[k];
    const mean = (v: number) => (s.w > 0 ? v / s.w : 0);
    out[id] = { area: s.w * o.atlas.texelSize ** 2, min: s.n ? s.min : 0, avg: mean(s.t), max: s.n ? s.max : 0, direct_avg: mean(s.d), indirect_avg: mean(s.i), texels: s.n };
  });
  return out;
}

/** What report.json says about an object's mesh besides the baker's statistics. */
export interface ObjectSource {
  /** The mesh path as the scene gives it. */
  mesh: string;
  triangles: number;
  /** The unit the import applied ('m' for glTF, detected for OBJ). */
  units: string;
  /** What orienting the mesh did (closed parts turned outward, open surfaces given back sides; docs/furniture.md). */
  orientation?: OrientationSummary;
}

/**
 * report.json: the contract fields first, then the baker's own report (`bake`, which keeps its
 * `objects` too). `objects` (scenes with objects) is the baker's per-object statistics, each with
 * its mesh path, triangle count, units and orientation.
 */
export function reportJson(scenePath: string, maps: BakedMaps, report: BakeReport, sources: readonly ObjectSource[] = []) {
  const { settings, timings_ms, ...bake } = report;
  const objects = report.objects;
  // A shaped room (issue 29): its own surfaces, from the atlas; the enclosure's sinks are not the room's.
  const room = maps.floor.layout.sink ? roomSurfaceIds(report) : null;
  return {
    scene: scenePath,
    surfaces: room ? summarizeRoomSurfaces(maps, room) : summarizeSurfaces(maps),
    // The room's surfaces lead a shaped room's objects: the scene's objects' sources start after them.
    ...(objects ? { objects: objects.map((o, i) => ({ ...o, ...(sources[i - (room?.length ?? 0)] ?? {}) })) } : {}),
    timings_ms,
    settings,
    bake,
  };
}

/** What report.json says about a room of any shape (lighting scene version 3): its geometry, which needs no baked map. */
export interface ShapedRoomReport {
  /** The floor polygon's area, m² (shoelace). */
  floor_area: number;
  /** Every surface of roomSurfaces ('floor', 'ceiling', 'slope-i', 'wall-i'; i as written): m² without its openings, and the openings' m². */
  surfaces: { id: string; kind: string; area: number; openings_area: number }[];
  /** m² of all openings (doors, windows, passages): where light leaves the room. */
  openings_area: number;
}

export function shapedRoomReport(room: ShapedRoom): ShapedRoomReport {
  const surfaces = roomSurfaces(room).map((s) => ({ id: s.id, kind: s.kind, area: s.area, openings_area: s.openings.reduce((a, o) => a + o.area, 0) }));
  return { floor_area: Math.abs(doubleSignedArea(room.corners)) / 2, surfaces, openings_area: surfaces.reduce((a, s) => a + s.openings_area, 0) };
}
