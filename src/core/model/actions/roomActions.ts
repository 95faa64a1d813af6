/**
 * Changing the room's size (a drawn room is scaled to it). The limits and every placed system's fit (walls, head room)
 * are validate()'s rules, checked on the result where the action is bound.
 */
import { z } from 'zod/mini';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import { requireRoomShapeSupport } from '../configuration/roomShapeSupport';

const setRoomParams = z.object({ width: z.number(), depth: z.number(), height: z.number() });

export const setRoom: ActionDefinition<z.infer<typeof setRoomParams>> = {
  name: 'setRoom',
  label: 'Room size',
  params: setRoomParams,
  perform(state, p) {
    if (!state.room.shape) return { ...state, room: { ...state.room, width: p.width, depth: p.depth, height: p.height } };
    // A drawn room is scaled to the new size by the room-shape chunk (scaleRoomShape.ts), loaded with the shape.
    return requireRoomShapeSupport().scale(state, p);
  },
  explain(problem) {
    return problem.path.startsWith('systems') ? quoting(`a placed system would not fit: ${problem.message}`, 'placedSystemWouldNotFit', problem) : problem.message;
  },
};
