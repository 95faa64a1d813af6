/**
 * Every user action by name: what the store dispatches and what the embedding
 * API lists. Parameters are validated with each action's zod schema.
 */
import { InputError } from '../../inputError';
import { enablementOf, refuse, type ActionDefinition, type Enablement, type Outcome, type UserAction } from './action';
import { bindDefinition } from './bindDefinition';
import type { Catalog } from '../catalogSchema/catalogSchema';
import { formatPath } from '../catalogSchema/catalogSchema';
import type { Configuration } from '../configuration/configuration';
import { setRoom } from './roomActions';
import { isRoomShapeActionName, ROOM_SHAPE_ACTION_LABELS, ROOM_SHAPE_ACTION_NAMES, type RoomShapeActionDefinitions } from './roomShapeActionNames';
import { roomShapeSupport, RoomShapeSupportMissing } from '../configuration/roomShapeSupport';
import { setReflectance } from './surfaceActions';
import { deleteSystem, moveSystem, placePreset, rotateSystem, setMounting, setSuspension } from './systemActions';
import { addFeed, moveFeed, removeFeed, setFeedDriver } from './feedActions';
import { addRail, removeRail, setDistribution, setRailLength } from './railActions';
import { moveFixingPoint, setJointTurn } from './chainShapeActions';
import { addBranch, setConnector } from './branchActions';
import { addModule, moveModule, removeModule, setModuleBeam, setModuleCct, setModuleDimming, setModuleType } from './moduleActions';
import { aimAt, setAim } from './aimActions';
import { autoPatch, clearPatch, setModulePatch } from './patchActions';
import { setModuleFilter } from './filterActions';
import { deleteScene, recallScene, recordScene, renameScene, reorderScene, setModuleOn, setSceneFade, updateScene } from './sceneActions';
import { addObject, moveObject, refinishObject, removeObject, resizeObject, rotateObject } from './objectActions';
import { safeParseInEnglish } from '../../zodEnglish';

/** The actions on the first screen by name; the room-shape editor's come with its chunk (roomShapeActionNames.ts): actionDefinition(name) finds either. */
export const actionDefinitions = {
  setRoom,
  setReflectance,
  placePreset,
  deleteSystem,
  moveSystem,
  rotateSystem,
  setSuspension,
  setMounting,
  addFeed,
  moveFeed,
  removeFeed,
  setFeedDriver,
  setRailLength,
  setDistribution,
  addRail,
  removeRail,
  addBranch,
  setConnector,
  setJointTurn,
  moveFixingPoint,
  addModule,
  moveModule,
  removeModule,
  setModuleType,
  setModuleCct,
  setModuleBeam,
  setModuleDimming,
  setModuleFilter,
  setModuleOn,
  setAim,
  aimAt,
  setModulePatch,
  autoPatch,
  clearPatch,
  addObject,
  moveObject,
  rotateObject,
  resizeObject,
  refinishObject,
  removeObject,
  recordScene,
  updateScene,
  renameScene,
  reorderScene,
  deleteScene,
  setSceneFade,
  recallScene,
} as const;

type ActionDefinitions = typeof actionDefinitions & RoomShapeActionDefinitions;
export type ActionName = keyof ActionDefinitions;
export type ActionParams<N extends ActionName> = ActionDefinitions[N] extends ActionDefinition<infer P> ? P : never;
// The room's size first, then its shape, then the rest as the table above lists them (docs/embedding.md's table follows this order).
export const ACTION_NAMES = ['setRoom', ...ROOM_SHAPE_ACTION_NAMES, ...Object.keys(actionDefinitions).filter((n) => n !== 'setRoom')] as ActionName[];

/** Bad action name or parameters (from a host page or the UI): the message names the field. */
export class ActionParamsError extends InputError {
  override name = 'ActionParamsError';
}

export function isActionName(name: string): name is ActionName {
  return (ACTION_NAMES as readonly string[]).includes(name);
}

/**
 * An action's definition by name. A room-shape action needs the room-shape chunk: before it is
 * installed (configuration/roomShapeSupport.ts) this throws RoomShapeSupportMissing; the UI and the
 * embedding API load the chunk before they offer or run one.
 */
export function actionDefinition(name: string): ActionDefinition<unknown> {
  if (!isActionName(name)) throw new ActionParamsError(`unknown action '${name}' (known: ${ACTION_NAMES.join(', ')})`);
  if (Object.prototype.hasOwnProperty.call(actionDefinitions, name)) return actionDefinitions[name as keyof typeof actionDefinitions] as ActionDefinition<unknown>;
  const support = roomShapeSupport();
  if (!support) throw new RoomShapeSupportMissing(name);
  return support.actions[name] as ActionDefinition<unknown>;
}

/** An action's label, known for every action on the first screen (a room-shape action's before its chunk has loaded too). */
export function actionLabel(name: ActionName): string {
  return isRoomShapeActionName(name) ? ROOM_SHAPE_ACTION_LABELS[name] : actionDefinitions[name].label;
}

/** Validates params for an action; throws ActionParamsError naming the bad field. */
export function parseActionParams(name: string, params: unknown): unknown {
  const r = safeParseInEnglish(actionDefinition(name).params, params);
  if (!r.success) {
    const issue = r.error.issues[0];
    throw new ActionParamsError(`${name}: ${formatPath(issue.path)}: ${issue.message}`);
  }
  return r.data;
}

/** An action bound to params and catalog: `{ name, isEnabled(state), perform(state), attempt(state) }`. Throws ActionParamsError for bad params. */
export function bindAction(name: string, params: unknown, catalog: Catalog): UserAction {
  return bindDefinition(actionDefinition(name), parseActionParams(name, params), catalog);
}

/** How many outcomes are kept for the latest state: more than the planner asks for on one screen. */
const MEMO_SIZE = 512;

/**
 * Outcomes asked for on the latest state, by action and params. The planner asks
 * whether each control is enabled and the store then runs the one clicked, on
 * the same state: the memo makes that one perform and one validation, not two.
 * Outcomes are pure functions of (catalog, state, name, params), and zod 4 has
 * already refused NaN and ±Infinity, so the params' JSON identifies them.
 */
let memo: { catalog: Catalog; state: Configuration; outcomes: Map<string, Outcome> } | undefined;

/**
 * JSON replacer for the memo key: an imported mesh's typed arrays (addObject) are keyed by
 * identity, not spelt out (a 100 000-vertex mesh would make a megabyte key per question).
 */
const bufferIds = new WeakMap<object, number>();
let nextBufferId = 0;
function paramsKey(_key: string, value: unknown): unknown {
  if (!ArrayBuffer.isView(value)) return value;
  let id = bufferIds.get(value);
  if (id === undefined) bufferIds.set(value, (id = nextBufferId++));
  return `#buffer${id}`;
}

/** What an action by name does to a state: the next state when enabled, else the refusal (bad names or params included). Never throws for bad input. */
export function attemptAction(state: Configuration, name: string, params: unknown, catalog: Catalog): Outcome {
  let action: UserAction;
  try {
    action = bindAction(name, params, catalog);
  } catch (e) {
    // A room-shape action before its chunk has loaded keeps its code (roomShapeLoading), for the UI's words.
    if (e instanceof InputError) return refuse(e.message, e);
    throw e;
  }
  if (memo?.state !== state || memo.catalog !== catalog) memo = { catalog, state, outcomes: new Map() };
  const key = `${name} ${JSON.stringify(action.params, paramsKey)}`;
  const known = memo.outcomes.get(key);
  if (known) return known;
  const outcome = action.attempt(state);
  const oldest = memo.outcomes.keys().next();
  if (memo.outcomes.size >= MEMO_SIZE && !oldest.done) memo.outcomes.delete(oldest.value);
  memo.outcomes.set(key, outcome);
  return outcome;
}

/** isEnabled by name; bad names or params come back as a refusal rather than an exception. */
export function checkAction(state: Configuration, name: string, params: unknown, catalog: Catalog): Enablement {
  return enablementOf(attemptAction(state, name, params, catalog));
}
