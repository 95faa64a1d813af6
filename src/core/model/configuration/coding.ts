/**
 * Codes for the core's English sentences (docs/i18n.md, "Messages from the core"). A problem's
 * `code` names the rule it breaks ('fixing-overhang'); where one rule is worded in several
 * sentences, `key` names the sentence, so a UI can word it in another language with `params`.
 * Both are non-enumerable, like a refusal's code: what tests, JSON and spreads see of a problem
 * stays `{ code, path, message }`.
 */
import { codedText, type CodedText, type MessageParams } from '../../inputError';

export interface Keyed {
  readonly key?: string;
  readonly params?: MessageParams;
}

/** `value` with its sentence's code and params attached as non-enumerable properties. */
export function keyed<const T extends object>(value: T, key: string, params?: MessageParams): T & Keyed {
  Object.defineProperty(value, 'key', { value: key, enumerable: false, configurable: true });
  if (params) Object.defineProperty(value, 'params', { value: params, enumerable: false, configurable: true });
  return value as T & Keyed;
}

/** A problem's sentence as a UI translates it: its own key when it has one, else its rule's code. */
export function problemText(problem: { readonly code: string; readonly message: string } & Keyed): CodedText {
  return codedText(problem.message, { code: problem.key ?? problem.code, params: problem.params });
}

/**
 * An action's sentence that quotes a problem ("cannot rotate here: <the problem>"): its own code
 * and the problem as `detail`, which a UI words first and passes as the parameter `problem`.
 */
export function quoting(reason: string, code: string, problem: { readonly code: string; readonly message: string } & Keyed, params?: MessageParams): { reason: string; code: string; params?: MessageParams; detail: CodedText } {
  return { reason, code, ...(params ? { params } : {}), detail: problemText(problem) };
}
