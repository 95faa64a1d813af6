/**
 * validate()'s rules for a room's shape (issue 29, docs/model.md "Room shape"); part of the
 * room-shape chunk (actions/roomShapeChunk.ts), which validate() asks through roomShapeSupport.
 */
import type { Configuration, RoomShape } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';
import { shapeProblems } from '../configuration/roomShape';
import { reflectanceProblem } from '../lightingScene/reflectance';
import { subProblem } from './roomProblems';

/** Float noise allowed between the outline's bounding box and the room's width and depth (a nanometre). */
const BOUNDS_EPS = 1e-9;

/**
 * A room's shape (docs/model.md, "Room shape"): its lists well formed, each wall's own finish a
 * configuration reflectance (≤ 0.95) and one per wall, the outline's bounding box exactly
 * [0, width] × [0, depth], then issue 29's room rules (src/core/room/roomProblems.ts) with their
 * codes and params, at the configuration's paths (room.shape.outline[3], room.shape.slopes[0].pitch).
 */
export function roomShapeProblems(room: Configuration['room'] & { shape: RoomShape }): Problem[] {
  const shape = room.shape as Partial<RoomShape> | null;
  const lists = ['outline', 'slopes', 'openings'] as const;
  const broken = lists.find((k) => !Array.isArray(shape?.[k]));
  if (typeof shape !== 'object' || shape === null || broken) {
    return [{ code: 'room-shape', path: `room.shape${broken ? `.${broken}` : ''}`, message: `the room's shape needs lists of corners, slopes and openings`, params: {} }];
  }
  const out: Problem[] = [];
  const finishes = room.shape.wallReflectance;
  if (finishes !== undefined) {
    if (!Array.isArray(finishes) || finishes.length !== room.shape.outline.length) {
      const count = Array.isArray(finishes) ? finishes.length : 0;
      out.push({ code: 'room-wall-reflectance-count', path: 'room.shape.wallReflectance', message: `the walls' finishes list ${count} entries for ${room.shape.outline.length} walls`, params: { count, walls: room.shape.outline.length } });
    } else {
      finishes.forEach((f, i) => {
        const problem = reflectanceProblem(f);
        if (problem) out.push(subProblem('reflectance', `room.shape.wallReflectance[${i}]`, problem));
      });
    }
  }
  if (out.length > 0) return out;
  const own = shapeProblems(room).map((p): Problem => ({ code: p.code, path: shapePath(p.path), message: p.message, params: p.params }));
  if (own.length > 0) return own;
  const xs = room.shape.outline.map((c) => c[0]);
  const zs = room.shape.outline.map((c) => c[1]);
  const [minX, maxX, minZ, maxZ] = [Math.min(...xs), Math.max(...xs), Math.min(...zs), Math.max(...zs)];
  const off = (v: number, want: number) => !(Math.abs(v - want) <= BOUNDS_EPS);
  if (off(minX, 0) || off(minZ, 0) || off(maxX, room.width) || off(maxZ, room.depth)) {
    const r = (v: number) => Math.round(v * 1000) / 1000;
    out.push({
      code: 'room-shape-bounds',
      path: 'room.shape.outline',
      message: `the outline spans x ${r(minX)} to ${r(maxX)} m and z ${r(minZ)} to ${r(maxZ)} m; it must span exactly 0 to the room's ${room.width} m width and 0 to its ${room.depth} m depth`,
      params: { minX: r(minX), maxX: r(maxX), minZ: r(minZ), maxZ: r(maxZ), width: room.width, depth: room.depth },
    });
  }
  return out;
}

/** A room-model path (room.outline[3], room.reflectance.walls[2]) at its place in the configuration. */
function shapePath(path: string): string {
  if (path === 'room.height' || path.startsWith('room.reflectance.floor') || path.startsWith('room.reflectance.ceiling')) return path;
  if (path.startsWith('room.reflectance.walls')) return path.replace('room.reflectance.walls', 'room.shape.wallReflectance');
  return path.replace(/^room\./, 'room.shape.');
}
