/**
 * Changing the room's size (a drawn room is scaled to it). The limits and every placed system's fit (walls, head room)
 * are validate()'s rules, checked on the result where the action is bound.
 */
import { z } from 'zod';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import { InputError } from '../../inputError';
import type { PlanPoint } from '../../room/planPolygon';
import { roomProblems } from '../../room/roomProblems';
import { settleShape, shapeRoomInput, wallLength } from './roomShapeGeometry';

const setRoomParams = z.object({ width: z.number(), depth: z.number(), height: z.number() });

export const setRoom: ActionDefinition<z.infer<typeof setRoomParams>> = {
  name: 'setRoom',
  label: 'Room size',
  params: setRoomParams,
  perform(state, p) {
    const shape = state.room.shape;
    if (!shape) return { ...state, room: { ...state.room, width: p.width, depth: p.depth, height: p.height } };
    // A drawn room is scaled to the new width and depth (docs/model.md, "Editing the room's shape"):
    // openings keep their size and their place along their wall in proportion.
    const sx = p.width / state.room.width;
    const sz = p.depth / state.room.depth;
    const outline = shape.outline.map((c): PlanPoint => [c[0] * sx, c[1] * sz]);
    const openings = shape.openings.map((o) => {
      const centre = (o.offset + o.width / 2) * (wallLength(outline, o.wall) / wallLength(shape.outline, o.wall));
      return { ...o, offset: Math.round((centre - o.width / 2) * 1000) / 1000 };
    });
    const next = settleShape({ ...state, room: { ...state.room, height: p.height } }, { ...shape, outline, openings });
    const problems = roomProblems(shapeRoomInput(next.room));
    if (problems.length > 0) throw new InputError(problems[0].message, { code: problems[0].code, params: problems[0].params });
    return next;
  },
  explain(problem) {
    return problem.path.startsWith('systems') ? quoting(`a placed system would not fit: ${problem.message}`, 'placedSystemWouldNotFit', problem) : problem.message;
  },
};
