/**
 * The always-valid action contract (configurator paper §3.2): every user action is
 * `{ name, isEnabled(state), perform(state) }` on immutable state. The UI
 * disables exactly what isEnabled refuses and shows the reason.
 *
 * A definition says only what is particular to it: its own refusals and how it
 * words a validation problem. "The result must pass validate()" is added once,
 * where a definition is bound (bindDefinition.ts), so it holds for every action
 * by construction. `perform` is the raw operation: it does not re-check anything,
 * so tests can prove that every refused action really would have broken validate().
 */
import type { z } from 'zod/mini';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { CodedText, MessageParams } from '../../inputError';
import type { Configuration } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';

export interface Refusal {
  readonly ok: false;
  /** One human-readable sentence: why the action is not possible now (English: the CLI, logs, the embedding API). */
  readonly reason: string;
  /** A stable code for the reason and its parameters, so a UI can show it in the user's language (docs/i18n.md, "Messages from the core"); absent where none is given yet. */
  readonly code?: string;
  readonly params?: MessageParams;
  /** The coded sentence the reason quotes ("cannot move it there: <the problem>"), worded first by a UI. */
  readonly detail?: CodedText;
}

/** A refusal sentence with its stable code: what `explain` and coded InputErrors carry. */
export interface CodedReason {
  readonly reason: string;
  readonly code: string;
  readonly params?: MessageParams;
  readonly detail?: CodedText;
}

/** `true` when the action may run, otherwise a refusal with the reason. */
export type Enablement = true | Refusal;

/** What running an action on a state gives: the next state, or why not. */
export type Outcome = { readonly ok: true; readonly next: Configuration } | Refusal;

/**
 * A refusal. Its `code` and `params` are readable but not enumerable: metadata for a UI that words
 * the reason in another language, while the refusal's data — what JSON, spreads and deep equality
 * see — stays `{ ok: false, reason }`.
 */
export function refuse(reason: string, coded?: { code?: string; params?: MessageParams; detail?: CodedText }): Refusal {
  const refusal: Refusal = { ok: false, reason };
  if (coded?.code) {
    Object.defineProperty(refusal, 'code', { value: coded.code, enumerable: false });
    if (coded.params) Object.defineProperty(refusal, 'params', { value: coded.params, enumerable: false });
    if (coded.detail) Object.defineProperty(refusal, 'detail', { value: coded.detail, enumerable: false });
  }
  return refusal;
}

/** Just the verdict of an outcome. */
export function enablementOf(outcome: Outcome): Enablement {
  return outcome.ok ? true : outcome;
}

/** An action definition: parameterised, catalog-aware. Registered by name in `actionDefinitions`. */
export interface ActionDefinition<P> {
  readonly name: string;
  /** Short label for buttons and menus. */
  readonly label: string;
  /** Validates the parameters (from UI, embedding API or a test). */
  readonly params: z.ZodMiniType<P>;
  /**
   * The action's own reasons to refuse, checked before perform. Leave out what
   * validate() already decides on the result: the binding checks that. Omitted: none.
   */
  isEnabled?(state: Configuration, params: P, catalog: Catalog): Enablement;
  /**
   * Raw transition. Throws InputError when it cannot be done at all (unknown id,
   * no free spot); the binding turns that into a refusal with the error's message.
   */
  perform(state: Configuration, params: P, catalog: Catalog): Configuration;
  /**
   * The refusal sentence for the first validation problem of the result, in the
   * action's words (e.g. "no room for another Spot"). Omitted: the problem's message.
   */
  explain?(problem: Problem, state: Configuration, params: P, catalog: Catalog): string | CodedReason;
}

/** An action bound to its parameters and catalog: the configurator paper's `{ isEnabled(state), perform(state) }`. */
export interface UserAction {
  readonly name: string;
  readonly params: unknown;
  /** The action's own reasons, then: the result must pass validate(). */
  isEnabled(state: Configuration): Enablement;
  /** Raw transition (no checks); reuses the state isEnabled or attempt computed for the same input. */
  perform(state: Configuration): Configuration;
  /** isEnabled and perform in one: the next state when enabled, else the refusal. */
  attempt(state: Configuration): Outcome;
}
