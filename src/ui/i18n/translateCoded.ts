import { isMessageKey } from './createTranslator';
import type { Area, MessageParams, Translate } from './messageTypes';

/** A message from code that cannot translate: English text for logs and the API, plus a stable code and its parameters. */
export interface CodedMessage {
  readonly text?: string;
  readonly reason?: string;
  readonly message?: string;
  readonly code?: string;
  readonly params?: Readonly<MessageParams>;
}

/**
 * The on-screen text of a message produced outside React (a core refusal, a validation problem,
 * a startup banner): `area.code` translated with its params when that key exists, else the
 * English sentence it carries (new codes show in English until translated, never as a key).
 */
export function translateCoded(t: Translate, area: Area, msg: CodedMessage): string {
  if (msg.code) {
    const key = `${area}.${msg.code}`;
    if (isMessageKey(key)) return t(key, msg.params);
  }
  return msg.text ?? msg.reason ?? msg.message ?? '';
}
