/** The room's rules (dimensions, surface reflectances) and the ids' (unique, below nextId). */
import { keyed, type Keyed } from '../configuration/coding';
import { ROOM_LIMITS, withinRoomLimits, type Configuration } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { SURFACE_NAMES } from '../lightingScene/lightingScene';
import { reflectanceProblem } from '../lightingScene/reflectance';
import { requireRoomShapeSupport } from '../configuration/roomShapeSupport';

export function roomProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  for (const key of ['width', 'depth', 'height'] as const) {
    const v = config.room[key];
    if (!withinRoomLimits(key, v)) {
      const { min, max } = ROOM_LIMITS[key];
      out.push(keyed({ code: 'room-dimension', path: `room.${key}`, message: `room ${key} must be between ${min} and ${max} m (got ${v})`, params: { dimension: key, min, max, value: v } }, ROOM_KEYS[key]));
    }
  }
  const reflectance = (config.room.reflectance ?? {}) as Record<string, unknown>;
  for (const surface of SURFACE_NAMES) {
    const problem = reflectanceProblem(reflectance[surface]);
    if (problem) out.push(subProblem('reflectance', `room.reflectance.${surface}`, problem));
  }
  // A room's shape (issue 29) is judged by the room-shape chunk (roomShapeSupport.ts), loaded before any shape can arrive.
  if (config.room.shape !== undefined) out.push(...requireRoomShapeSupport().problems(config.room));
  // Daylight and the windows' glazing (issue 30) are judged by the same chunk.
  if (out.length === 0 && (config.room.shape !== undefined || config.daylight !== undefined)) out.push(...requireRoomShapeSupport().daylightProblems(config));
  return out;
}

export function idProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  const seen = new Set<string>();
  const check = (id: string, path: string) => {
    if (seen.has(id)) out.push(keyed({ code: 'duplicate-id', path, message: `id '${id}' is used twice` }, 'duplicateId', { id }));
    seen.add(id);
    const m = /^[a-z](\d+)$/.exec(id);
    if (m && Number(m[1]) >= config.nextId) out.push(keyed({ code: 'id-counter', path, message: `id '${id}' is not below nextId ${config.nextId}` }, 'idCounter', { id, next: config.nextId }));
  };
  config.objects.forEach((o, i) => check(o.id, `objects[${i}].id`));
  (config.lightScenes ?? []).forEach((s, i) => check(s.id, `lightScenes[${i}].id`));
  Object.keys(config.importedMeshes).forEach((id) => check(id, `importedMeshes.${id}`));
  config.systems.forEach((s, i) => {
    check(s.id, `systems[${i}].id`);
    s.feeds.forEach((f, k) => check(f.id, `systems[${i}].feeds[${k}].id`));
    s.rails.forEach((r, k) => {
      check(r.id, `systems[${i}].rails[${k}].id`);
      r.modules.forEach((m, n) => check(m.id, `systems[${i}].rails[${k}].modules[${n}].id`));
    });
  });
  return out;
}

/** The sentence key of each room dimension's range problem. */
const ROOM_KEYS = { width: 'roomWidthRange', depth: 'roomDepthRange', height: 'roomHeightRange' } as const;

/** A problem whose sentence a sub-rule wrote, with that rule's coding (reflectance.ts …). */
export function subProblem(code: string, path: string, found: string | ({ message: string } & Keyed)): Problem {
  if (typeof found === 'string') return { code, path, message: found };
  return found.key ? keyed({ code, path, message: found.message }, found.key, found.params) : { code, path, message: found.message };
}
