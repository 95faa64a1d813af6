/** Changing the room. Refused when a dimension is out of range or a placed system would no longer fit. */
import { z } from 'zod';
import { refuse, type ActionDefinition } from '../action';
import { ROOM_LIMITS } from '../configuration';
import { roomProblems } from '../validate';
import { systemFits } from './lookup';

const setRoomParams = z.object({ width: z.number(), depth: z.number(), height: z.number() });

export const setRoom: ActionDefinition<z.infer<typeof setRoomParams>> = {
  name: 'setRoom',
  label: 'Room size',
  params: setRoomParams,
  isEnabled(state, p, catalog) {
    for (const key of ['width', 'depth', 'height'] as const) {
      const { min, max } = ROOM_LIMITS[key];
      if (p[key] < min || p[key] > max) return refuse(`room ${key} must be between ${min} and ${max} m`);
    }
    const candidate = setRoom.perform(state, p, catalog);
    if (roomProblems(candidate).length > 0) return refuse(roomProblems(candidate)[0].message);
    for (let i = 0; i < candidate.systems.length; i++) {
      const fit = systemFits(candidate, i, catalog);
      if (fit !== true) return refuse(`a placed system would not fit: ${fit.reason}`);
    }
    return true;
  },
  perform(state, p) {
    return { ...state, room: { ...state.room, width: p.width, depth: p.depth, height: p.height } };
  },
};
