/**
 * Changing the room. The limits and every placed system's fit (walls, head room)
 * are validate()'s rules, checked on the result where the action is bound.
 */
import { z } from 'zod/mini';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';

const setRoomParams = z.object({ width: z.number(), depth: z.number(), height: z.number() });

export const setRoom: ActionDefinition<z.infer<typeof setRoomParams>> = {
  name: 'setRoom',
  label: 'Room size',
  params: setRoomParams,
  perform(state, p) {
    return { ...state, room: { ...state.room, width: p.width, depth: p.depth, height: p.height } };
  },
  explain(problem) {
    return problem.path.startsWith('systems') ? quoting(`a placed system would not fit: ${problem.message}`, 'placedSystemWouldNotFit', problem) : problem.message;
  },
};
