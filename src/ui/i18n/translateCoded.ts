import { isMessageKey } from './createTranslator';
import type { Area, MessageKey, MessageParams, Translate } from './messageTypes';

/** A message from code that cannot translate: English text for logs and the API, plus a stable code and its parameters. */
export interface CodedMessage {
  readonly text?: string;
  readonly reason?: string;
  readonly message?: string;
  readonly code?: string;
  readonly params?: Readonly<MessageParams>;
  /** A coded sentence the message quotes (docs/i18n.md): worded first, then passed as the parameter `problem`. */
  readonly detail?: CodedMessage;
}

/** Turns a message's raw parameters into what its sentence shows (a catalog id into a name, a wall into its word). */
export type LocaliseParams = (params: MessageParams) => MessageParams;

/**
 * The areas that hold the core's codes, tried after the caller's own area: the planner asks
 * `notices` and finds a validation problem in `refusals`, a scene file's error in `fileErrors`,
 * a photometric file's in `photometry`.
 */
const CORE_AREAS: readonly Area[] = ['notices', 'refusals', 'fileErrors', 'photometry'];

/**
 * The on-screen text of a message produced outside React (a core refusal, a validation problem,
 * a file error, a startup banner): `area.code` (else the same code in the core's areas) translated
 * with its params when that key exists, else the English sentence it carries (new codes show in
 * English until translated, never as a key). A quoted `detail` is translated the same way and
 * becomes the parameter `problem`; a `what` parameter is worded by `<area>.what_<value>`.
 */
export function translateCoded(t: Translate, area: Area, msg: CodedMessage, localise?: LocaliseParams): string {
  if (msg.code) {
    for (const a of [area, ...CORE_AREAS.filter((x) => x !== area)]) {
      const key = `${a}.${msg.code}`;
      if (!isMessageKey(key)) continue;
      let params: MessageParams = msg.params ? { ...msg.params } : {};
      if (msg.detail) params.problem = translateCoded(t, area, msg.detail, localise);
      if (typeof params.what === 'string') {
        const word = `${a}.what_${params.what}`;
        if (isMessageKey(word)) params.what = t(word);
      }
      if (localise) params = localise(params);
      const text = t(key as MessageKey, params);
      // A parameter the message needs and the code did not bring (a quoted problem lost on the way): the English sentence, never "{problem}".
      if (/\{\w+\}/.test(text)) break;
      return text;
    }
  }
  return msg.text ?? msg.reason ?? msg.message ?? '';
}
