/** The finishes' rules (issue 29): every reflectance a number in [0, 1) or [r, g, b]; per-wall lists one entry per wall. */
import type { RoomInput, RoomReflectance } from './roomInput';
import { problem, reflectanceOk, type RoomProblem } from './roomProblem';

export function reflectanceProblems(reflectance: RoomInput['reflectance'] | undefined, n: number): RoomProblem[] {
  const out: RoomProblem[] = [];
  const r = (reflectance ?? {}) as Partial<RoomInput['reflectance']>;
  for (const key of ['floor', 'ceiling'] as const) {
    if (!reflectanceOk(r[key])) out.push(problem('room-reflectance', `room.reflectance.${key}`, `the ${key}'s reflectance must be a number in [0, 1) or [r, g, b]`, { surface: key }));
  }
  const walls = r.walls;
  const perWall = Array.isArray(walls) && !(walls.length === 3 && walls.every((v) => typeof v === 'number'));
  if (perWall) {
    const list = walls as readonly RoomReflectance[];
    if (list.length !== n) {
      out.push(problem('room-wall-reflectance-count', 'room.reflectance.walls', `the walls' reflectances list ${list.length} entries for ${n} walls`, { count: list.length, walls: n }));
    } else {
      list.forEach((v, i) => {
        if (!reflectanceOk(v)) out.push(problem('room-reflectance', `room.reflectance.walls[${i}]`, `wall ${i}: a reflectance must be a number in [0, 1) or [r, g, b]`, { surface: `wall ${i}` }));
      });
    }
  } else if (!reflectanceOk(walls)) {
    out.push(problem('room-reflectance', 'room.reflectance.walls', "the walls' reflectance must be a number in [0, 1), [r, g, b], or one of these per wall", { surface: 'walls' }));
  }
  return out;
}
