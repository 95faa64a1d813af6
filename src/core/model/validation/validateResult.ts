/**
 * validate() of an action's result, paying only for what the action changed.
 * States are immutable and actions replace only the systems they touch (the
 * others stay the same objects), so when the state before was valid and the room
 * keeps its size, the result is valid exactly when its room finishes, ids and
 * DMX patch (no shared channels) and light scenes are, and each new or replaced system passes systemProblems() (its own rules,
 * the room bounds, self-crossing, clashes with every other system): an
 * untouched system keeps its own validity, and a pair of untouched systems
 * still does not clash. Anything else (a resized room, an invalid state
 * before) gets the full validate(). The planner asks this for every control on
 * every render, so a hall of hundreds of rails must not pay a full validate()
 * per button.
 */
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration } from '../configuration/configuration';
import { lightSceneProblems } from '../cues/lightScenes';
import { changedObjectProblems } from '../objects/objectProblems';
import { validate } from './validate';
import { idProblems, roomProblems } from './roomProblems';
import { patchProblems } from './patchProblems';
import { systemProblems } from './systemProblems';
import { type Problem } from '../configuration/problem';

/** Per catalog, whether a state passed validate(): states are immutable, so the answer never changes. */
const knownValid = new WeakMap<Catalog, WeakMap<Configuration, boolean>>();

function statesOf(catalog: Catalog): WeakMap<Configuration, boolean> {
  let states = knownValid.get(catalog);
  if (!states) knownValid.set(catalog, (states = new WeakMap()));
  return states;
}

function isValid(state: Configuration, catalog: Catalog): boolean {
  const states = statesOf(catalog);
  let valid = states.get(state);
  if (valid === undefined) {
    valid = validate(state, catalog, { firstOnly: true }).length === 0;
    states.set(state, valid);
  }
  return valid;
}

/** The problems of `after` (empty exactly when validate(after) is), the first one first; `before` is the state it came from. */
export function validateResult(before: Configuration, after: Configuration, catalog: Catalog): Problem[] {
  const resized = before.room.width !== after.room.width || before.room.depth !== after.room.depth || before.room.height !== after.room.height;
  const problems = resized || !isValid(before, catalog) ? validate(after, catalog, { firstOnly: true }) : changedProblems(before, after, catalog);
  // Remembered so the next action on this state (the store's new present) takes the cheap path.
  statesOf(catalog).set(after, problems.length === 0);
  return problems;
}

function changedProblems(before: Configuration, after: Configuration, catalog: Catalog): Problem[] {
  const room = roomProblems(after);
  if (room.length > 0) return room;
  const ids = idProblems(after);
  if (ids.length > 0) return ids;
  // The patch spans systems: a changed module's channels may meet an untouched system's (one sort over the patched modules).
  const patch = patchProblems(after);
  if (patch.length > 0) return patch;
  // Light scenes: cheap (one pass over the looks), and any action may touch them (a removed module leaves every look).
  if (after.lightScenes !== before.lightScenes || after.systems !== before.systems) {
    const scenes = lightSceneProblems(after);
    if (scenes.length > 0) return scenes;
  }
  const untouched = new Set(before.systems);
  for (let i = 0; i < after.systems.length; i++) {
    if (untouched.has(after.systems[i])) continue;
    const problems = systemProblems(after, i, catalog);
    if (problems.length > 0) return problems;
  }
  // Objects do not interact with systems or each other: only new or replaced ones (and the meshes) need a look.
  return changedObjectProblems(before, after);
}
