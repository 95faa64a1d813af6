import { InputError } from '../core/inputError';
import { normaliseRoom, type Room } from '../core/room/normaliseRoom';
import type { RoomInput } from '../core/room/roomInput';
import { ReferenceInputError } from './referenceInputError';

/** The room a reference solver works in (normaliseRoom), its rule problems as the reference's own input error. */
export function referenceRoom(input: RoomInput): Room {
  try {
    return normaliseRoom(input);
  } catch (e) {
    if (e instanceof InputError) throw new ReferenceInputError(e.message);
    throw e;
  }
}
