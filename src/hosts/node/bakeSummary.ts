import type { OrientationSummary } from '../../core/mesh/orientMesh';
import { SURFACE_NAMES, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import { luxOf, type BakedMaps } from '../../engines/bake/bakedMaps';
import type { BakeReport } from '../../engines/bake/createBaker';
import { texelArea } from '../../engines/bake/surfaceLayout';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { doubleSignedArea } from '../../core/room/planPolygon';
import { roomSurfaces } from '../../core/room/roomSurfaces';

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
  return {
    scene: scenePath,
    surfaces: summarizeSurfaces(maps),
    ...(objects ? { objects: objects.map((o, i) => ({ ...o, ...(sources[i] ?? {}) })) } : {}),
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
