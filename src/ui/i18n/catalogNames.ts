import type { Translate } from './messageTypes';
import { translateCoded } from './translateCoded';

/** A surface or object finish's name: `finishes.<id>` when translated, else the name it carries. */
export function finishName(t: Translate, finish: { id: string; name: string }): string {
  return translateCoded(t, 'finishes', { code: finish.id, text: finish.name });
}

/** A furniture library item's name: `furniture.<id>` when translated, else its English name. */
export function furnitureName(t: Translate, item: { id: string; name: string }): string {
  return translateCoded(t, 'furniture', { code: item.id, text: item.name });
}

/** A furnished room preset's name: `rooms.<id>` when translated, else its English name. */
export function roomName(t: Translate, room: { id: string; name: string }): string {
  return translateCoded(t, 'rooms', { code: room.id, text: room.name });
}
