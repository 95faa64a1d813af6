/**
 * Every user action by name: what the store dispatches and what the embedding
 * API lists. Parameters are validated with each action's zod schema.
 */
import { InputError } from '../inputError';
import { refuse, type ActionDefinition, type Enablement, type UserAction } from './action';
import type { Catalog } from './catalogSchema';
import { formatPath } from './catalogSchema';
import type { Configuration } from './configuration';
import { setRoom } from './actions/roomActions';
import { setReflectance } from './actions/surfaceActions';
import { deleteSystem, moveSystem, placePreset, rotateSystem, setSuspension } from './actions/systemActions';
import { addRail, removeRail, setDistribution, setRailLength } from './actions/railActions';
import { addModule, removeModule, setModuleBeam, setModuleCct, setModuleDimming, setModuleType } from './actions/moduleActions';

export const actionDefinitions = {
  setRoom,
  setReflectance,
  placePreset,
  deleteSystem,
  moveSystem,
  rotateSystem,
  setSuspension,
  setRailLength,
  setDistribution,
  addRail,
  removeRail,
  addModule,
  removeModule,
  setModuleType,
  setModuleCct,
  setModuleBeam,
  setModuleDimming,
} as const;

export type ActionName = keyof typeof actionDefinitions;
export type ActionParams<N extends ActionName> = (typeof actionDefinitions)[N] extends ActionDefinition<infer P> ? P : never;
export const ACTION_NAMES = Object.keys(actionDefinitions) as ActionName[];

/** Bad action name or parameters (from a host page or the UI): the message names the field. */
export class ActionParamsError extends InputError {
  override name = 'ActionParamsError';
}

export function isActionName(name: string): name is ActionName {
  return Object.prototype.hasOwnProperty.call(actionDefinitions, name);
}

function definition(name: string): ActionDefinition<unknown> {
  if (!isActionName(name)) throw new ActionParamsError(`unknown action '${name}' (known: ${ACTION_NAMES.join(', ')})`);
  return actionDefinitions[name] as ActionDefinition<unknown>;
}

/** Validates params for an action; throws ActionParamsError naming the bad field. */
export function parseActionParams(name: string, params: unknown): unknown {
  const r = definition(name).params.safeParse(params);
  if (!r.success) {
    const issue = r.error.issues[0];
    throw new ActionParamsError(`${name}: ${formatPath(issue.path)}: ${issue.message}`);
  }
  return r.data;
}

/** An action bound to params and catalog: `{ name, isEnabled(state), perform(state) }`. Throws ActionParamsError for bad params. */
export function bindAction(name: string, params: unknown, catalog: Catalog): UserAction {
  const def = definition(name);
  const parsed = parseActionParams(name, params);
  return {
    name,
    params: parsed,
    isEnabled: (state: Configuration) => def.isEnabled(state, parsed, catalog),
    perform: (state: Configuration) => def.perform(state, parsed, catalog),
  };
}

/** isEnabled by name; bad names or params come back as a refusal rather than an exception. */
export function checkAction(state: Configuration, name: string, params: unknown, catalog: Catalog): Enablement {
  try {
    return bindAction(name, params, catalog).isEnabled(state);
  } catch (e) {
    if (e instanceof InputError) return refuse(e.message);
    throw e;
  }
}
