import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { InputError } from '../../core/inputError';
import { SURFACE_NAMES } from '../../core/model/lightingScene/lightingScene';
import { luxOf, type BakedMaps } from '../../engines/bake/bakedMaps';
import type { BakeReport } from '../../engines/bake/createBaker';
import { reportJson, roomSurfaceIds, type ObjectSource } from './bakeSummary';
import { ROOM_OBJECT_PREFIX } from '../../engines/bake/shapedRoom/roomSurfaceObjects';

/** Total lux of every covered atlas texel (a shaped room's surfaces and objects): the PNG scale's sample. */
function coveredLux(maps: BakedMaps): number[] {
  const o = maps.objects;
  if (!o) return [];
  const y = luxOf(o.total);
  return Array.from(y).filter((_, k) => o.atlas.position[4 * k + 3] > 0);
}
import type { LightingObject } from '../../core/model/lightingScene/lightingScene';
import { writeObjectMaps } from './writeObjectMaps';
import { falseColorPng } from './falseColorPng';
import { writePfm } from './writePfm';

/** The scene's objects as report.json and objects.json name them. */
export interface SceneObjectsOutput {
  objects: readonly LightingObject[];
  ids: readonly string[];
  sources: readonly ObjectSource[];
}

/**
 * What `luxbox bake` writes for one scene (docs/scene-format.md, "Command-line contract"): report.json,
 * per surface <name>.direct/.indirect/.total.pfm (RGB lux) and <name>.png
 * (false colour of total lux, one scale for all six), and with objects the atlas's
 * objects.direct/.indirect/.total.pfm, objects.png, objects.mask.pfm and objects.json.
 */
export function writeBakeOutput(out: string, scenePath: string, maps: BakedMaps, report: BakeReport, extra: Record<string, unknown> = {}, objects: SceneObjectsOutput = { objects: [], ids: [], sources: [] }): void {
  const started = performance.now();
  try {
    mkdirSync(out, { recursive: true });
  } catch (error) {
    throw new InputError(`--out ${out}: cannot create the folder (${(error as NodeJS.ErrnoException).code ?? 'error'})`);
  }
  // One colour scale for all surfaces: the 99.5th percentile of total lux, so a
  // lamp touching a wall does not turn every other surface dark blue.
  // A shaped room (issue 29): its surfaces are the atlas's first objects; the enclosure's six sinks are not written.
  const room = maps.floor.layout.sink ? roomSurfaceIds(report) : [];
  const shaped = maps.floor.layout.sink === true;
  const all = (shaped ? coveredLux(maps) : SURFACE_NAMES.flatMap((n) => Array.from(luxOf(maps[n].total)))).sort((a, b) => a - b);
  const scaleMax = all.length ? all[Math.min(all.length - 1, Math.floor(all.length * 0.995))] : 1;
  for (const name of shaped ? [] : SURFACE_NAMES) {
    const m = maps[name];
    const { width, height } = m.layout;
    writePfm(join(out, `${name}.direct.pfm`), width, height, m.direct);
    writePfm(join(out, `${name}.indirect.pfm`), width, height, m.indirect);
    writePfm(join(out, `${name}.total.pfm`), width, height, m.total);
    writeFileSync(join(out, `${name}.png`), falseColorPng(luxOf(m.total), width, height, scaleMax));
  }
  if (maps.objects) {
    // The room's surfaces lead the atlas's objects: they come first in objects.json, as '(room)' meshes.
    const roomObjects = room.map((id): LightingObject => ({ mesh: '(room)', position: [0, 0, 0], yaw: 0, scale: 1, id: ROOM_OBJECT_PREFIX + id }));
    writeObjectMaps(out, maps.objects, [...roomObjects, ...objects.objects], [...roomObjects.map((o) => o.id!), ...objects.ids], scaleMax);
  }
  const json = reportJson(scenePath, maps, report, objects.sources);
  json.timings_ms = { ...json.timings_ms, write: performance.now() - started } as typeof json.timings_ms;
  writeFileSync(join(out, 'report.json'), JSON.stringify({ ...json, ...extra, png_scale_max_lux: scaleMax }, null, 2) + '\n');
}
