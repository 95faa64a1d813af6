/**
 * Binding a definition to its parameters and catalog: the one place where "an
 * action is refused only if its result would be invalid" is enforced. A bound
 * action is enabled when the definition's own isEnabled (if any) agrees, perform
 * does not throw InputError, and validate() accepts the result; so no action,
 * present or future, can lead the store to an invalid state, whatever its own
 * isEnabled says.
 */
import { InputError } from '../../inputError';
import { enablementOf, refuse, type ActionDefinition, type Outcome, type UserAction } from './action';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration } from '../configuration/configuration';
import { keyed, problemText } from '../configuration/coding';
import { overloadRefusal } from '../power/feedLoads';
import { pruneLooks } from '../cues/lightScenes';
import { validateResult } from '../validation/validateResult';

interface Decision {
  readonly state: Configuration;
  readonly outcome: Outcome;
  /** The performed state, valid or not, when perform ran. */
  readonly performed?: Configuration;
}

function decide<P>(def: ActionDefinition<P>, state: Configuration, params: P, catalog: Catalog): Decision {
  let performed: Configuration;
  try {
    const own = def.isEnabled?.(state, params, catalog) ?? true;
    if (own !== true) return { state, outcome: own };
    // Looks of modules the action removed leave every light scene with them (lightScenes.ts).
    performed = pruneLooks(def.perform(state, params, catalog));
  } catch (e) {
    // Unknown ids, unknown catalog entries, nowhere to put it: bad input, not a bug.
    if (e instanceof InputError) return { state, outcome: refuse(e.message, e) };
    throw e;
  }
  const problems = validateResult(state, performed, catalog);
  if (problems.length === 0) return { state, outcome: { ok: true, next: performed }, performed };
  // An overloaded driver is worded once for every action (addModule, setModuleBeam, presets, moves…): how full it was.
  const overload = problems[0].code === 'feed-overload' ? overloadRefusal(state, performed, problems[0], catalog) : null;
  // The overload's coding goes with its sentence, so an action that quotes the problem quotes it coded.
  const first = overload ? (overload.code ? keyed({ ...problems[0], message: overload.reason }, overload.code, overload.params) : { ...problems[0], message: overload.reason }) : problems[0];
  const explained = def.explain?.(first, state, params, catalog) ?? first.message;
  // The code travels with the sentence it names: the action's own coded reason, or the overload's when the action kept its wording.
  if (typeof explained !== 'string') return { state, outcome: refuse(explained.reason, explained), performed };
  // When the action kept the problem's own sentence, the problem's code and params name it.
  const coded = explained === first.message ? problemText(first) : undefined;
  return { state, outcome: refuse(explained, coded), performed };
}

/**
 * `{ isEnabled(state), perform(state), attempt(state) }` for already parsed params.
 * The last decision is kept, so asking isEnabled and then performing on the same
 * state runs perform once.
 */
export function bindDefinition<P>(def: ActionDefinition<P>, params: P, catalog: Catalog): UserAction {
  let last: Decision | undefined;
  const attempt = (state: Configuration): Outcome => {
    if (last?.state !== state) last = decide(def, state, params, catalog);
    return last.outcome;
  };
  return {
    name: def.name,
    params,
    attempt,
    isEnabled: (state) => enablementOf(attempt(state)),
    perform: (state) => (last?.state === state && last.performed ? last.performed : pruneLooks(def.perform(state, params, catalog))),
  };
}
