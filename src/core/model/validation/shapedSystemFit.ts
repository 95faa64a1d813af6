/** A system's fit in a room of any shape (docs/model.md "Room shape"); part of the room-shape chunk (actions/roomShapeChunk.ts). */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { LightSystem, Room, RoomShape } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { keyed } from '../configuration/coding';
import { shapedRoom, shapeProblems } from '../configuration/roomShape';
import { footprintInsideOutline, lowestCeilingOver } from '../../room/footprintInsideRoom';
import { photometricDrop } from '../rails/suspensionPoints';
import type { PlanPoint } from '../../room/planPolygon';
import { EPS } from './reporting';

/**
 * Whether a sound system that fits the box fits its room of any shape (issue 29): every rail, connector and module rectangle inside the outline (footprintInsideOutline: a rail
 * past the inner corner of an L is outside even with both ends in the room) and clear of the
 * ceiling above it. Under a slope a pendant system's wires grow shorter toward the slope (each
 * fixing point's wire is the ceiling above it less the modules' height, suspensionWireLength);
 * along every rectangle the ceiling must stay at least the shortest suspension (catalog
 * suspension.min, ceiling to photometric centre) above the modules, checked at the rectangle's
 * corners since the ceiling is concave. A surface-mounted system's clips need the flat ceiling
 * over its whole footprint. A shape that breaks its own rules is the room's problem, not the
 * system's: then only the box is checked.
 */
export function shapedSystemFit(s: LightSystem, index: number, rects: readonly (readonly PlanPoint[])[], room: Room, catalog: Catalog): Problem | null {
  if (!room.shape || shapeProblems(room as Room & { shape: RoomShape }).length > 0) return null;
  const shaped = shapedRoom(room)!;
  if (rects.some((c) => !footprintInsideOutline(shaped.corners, c, EPS))) {
    // Its own sentence key: 'outside-room' alone is the box's sentence, with the room's width and depth.
    return keyed({ code: 'outside-room', path: `systems[${index}]`, message: `system ${s.id} reaches outside the room's outline`, params: { id: s.id } }, 'outsideOutline');
  }
  const lowest = Math.min(...rects.map((c) => lowestCeilingOver(shaped, c)));
  const at = `systems[${index}]`;
  if (s.mounting === 'surface') {
    if (lowest < room.height - EPS) {
      const message = `system ${s.id} is mounted on the ceiling but reaches under a slope (${fmt(lowest)} m there); clips need the flat ${fmt(room.height)} m ceiling`;
      return keyed({ code: 'under-slope', path: `${at}.mounting`, message, params: { id: s.id, ceiling: Number(fmt(lowest)), height: room.height } }, 'underSlopeClips');
    }
    return null;
  }
  const modules = room.height - photometricDrop(s, catalog);
  const clearance = lowest - modules;
  const min = catalog.suspension.min;
  if (clearance < min - EPS) {
    const message = `system ${s.id} hangs ${fmt(clearance)} m under a slope at its closest; the ceiling must stay at least ${min} m above its modules`;
    return keyed({ code: 'under-slope', path: `${at}.suspension`, message, params: { id: s.id, clearance: Number(fmt(clearance)), min } }, 'underSlopeClearance');
  }
  return null;
}

const fmt = (x: number): string => String(Math.round(x * 1000) / 1000);
