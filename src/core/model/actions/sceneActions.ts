/**
 * Light scenes (cues, docs/light-scenes.md): record, update, rename, reorder, delete, fade time,
 * recall, and switching a module on or off. All undoable like every action; names, fade range
 * and looks are validate()'s rules (lightScenes.ts), checked on the result where the action is bound.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { ActionDefinition, CodedReason } from './action';
import type { Configuration, LightScene } from '../configuration/configuration';
import { FADE_LIMITS, findScene, looksOf, recallLooks, SCENE_NAME_MAX, sceneByName } from '../cues/lightScenes';
import type { Problem } from '../configuration/problem';
import { findModule, replaceRail, takeId } from './lookup';

function sceneIndex(state: Configuration, sceneId: string): number {
  const i = (state.lightScenes ?? []).findIndex((s) => s.id === sceneId);
  if (i < 0) throw new InputError(`no light scene with id '${sceneId}'`, { code: 'unknownScene', params: { id: sceneId } });
  return i;
}

function replaceScene(state: Configuration, sceneId: string, patch: Partial<LightScene>): Configuration {
  const i = sceneIndex(state, sceneId);
  return { ...state, lightScenes: state.lightScenes!.map((s, k) => (k === i ? { ...s, ...patch } : s)) };
}

/**
 * A scene-name problem in the user's words, with a stable code the scene panel translates
 * (i18n area 'scenes'): the name is missing, too long, or taken by another scene.
 */
function explainName(problem: Problem, state: Configuration, name: string): string | CodedReason {
  if (problem.code === 'scene-name-taken') {
    const taken = sceneByName(state, name)?.name ?? name.trim();
    return { reason: `a light scene named '${taken}' exists already`, code: 'nameTaken', params: { name: taken } };
  }
  if (problem.code === 'scene-name') {
    return name.trim() === '' ? { reason: 'a light scene needs a name', code: 'nameMissing' } : { reason: `a light scene name has at most ${SCENE_NAME_MAX} characters`, code: 'nameTooLong', params: { max: SCENE_NAME_MAX } };
  }
  return problem.message;
}

/** The default fade of a new scene, seconds: a calm change, as a console's default cue time (ETC Eos: 5 s; we take 3 s, issue #12's example). */
export const DEFAULT_FADE = 3;

const recordParams = z.object({ name: z.string(), fade: z.optional(z.number()) });

/** Stores every module's on/off, level, CCT and filter as a new scene at the end of the list. */
export const recordScene: ActionDefinition<z.infer<typeof recordParams>> = {
  name: 'recordScene',
  label: 'Record scene',
  params: recordParams,
  perform(state, p) {
    const [id, next] = takeId(state, 'q');
    const scene: LightScene = { id, name: p.name.trim(), fade: p.fade ?? DEFAULT_FADE, looks: looksOf(state) };
    return { ...next, lightScenes: [...(state.lightScenes ?? []), scene] };
  },
  explain: (problem, state, p) => explainName(problem, state, p.name),
};

const sceneIdParams = z.object({ sceneId: z.string() });

/** Replaces a scene's looks with the current state of every module. */
export const updateScene: ActionDefinition<z.infer<typeof sceneIdParams>> = {
  name: 'updateScene',
  label: 'Update scene',
  params: sceneIdParams,
  perform: (state, p) => replaceScene(state, p.sceneId, { looks: looksOf(state) }),
};

const renameParams = z.object({ sceneId: z.string(), name: z.string() });

export const renameScene: ActionDefinition<z.infer<typeof renameParams>> = {
  name: 'renameScene',
  label: 'Rename scene',
  params: renameParams,
  perform: (state, p) => replaceScene(state, p.sceneId, { name: p.name.trim() }),
  // The scene itself has the name already: renaming to its own name (other case) is not a clash.
  explain: (problem, state, p) => explainName(problem, { ...state, lightScenes: state.lightScenes?.filter((s) => s.id !== p.sceneId) }, p.name),
};

const reorderParams = z.object({ sceneId: z.string(), index: z.number().check(z.int()) });

/** Moves a scene to position `index` of the playback order (GO / BACK follow it). */
export const reorderScene: ActionDefinition<z.infer<typeof reorderParams>> = {
  name: 'reorderScene',
  label: 'Move scene',
  params: reorderParams,
  perform(state, p) {
    // Thrown, not a refusal in isEnabled: a refused action's perform must not produce a valid state (the always-valid property).
    const n = state.lightScenes?.length ?? 0;
    if (p.index < 0 || p.index >= n) throw new InputError(`position ${p.index + 1} is outside the list of ${n} scenes`, { code: 'positionOutside', params: { position: p.index + 1, count: n } });
    const i = sceneIndex(state, p.sceneId);
    const list = [...state.lightScenes!];
    const [scene] = list.splice(i, 1);
    list.splice(p.index, 0, scene);
    return { ...state, lightScenes: list };
  },
};

export const deleteScene: ActionDefinition<z.infer<typeof sceneIdParams>> = {
  name: 'deleteScene',
  label: 'Delete scene',
  params: sceneIdParams,
  perform(state, p) {
    const i = sceneIndex(state, p.sceneId);
    const list = state.lightScenes!.filter((_, k) => k !== i);
    if (list.length > 0) return { ...state, lightScenes: list };
    const { lightScenes: _gone, ...rest } = state;
    return rest;
  },
};

const fadeParams = z.object({ sceneId: z.string(), fade: z.number() });

export const setSceneFade: ActionDefinition<z.infer<typeof fadeParams>> = {
  name: 'setSceneFade',
  label: 'Fade time',
  params: fadeParams,
  perform: (state, p) => replaceScene(state, p.sceneId, { fade: p.fade }),
  explain: (problem) => (problem.code === 'scene-fade' ? { reason: `a fade takes ${FADE_LIMITS.min} to ${FADE_LIMITS.max} s`, code: 'fadeRange', params: { min: FADE_LIMITS.min, max: FADE_LIMITS.max } } : problem.message),
};

/**
 * Applies a scene's looks (the end state of a crossfade: the fade itself is playback, not
 * configuration). A module the scene does not list keeps its state; a stored CCT or filter the
 * module's type can no longer take is left as it is (lightScenes.ts applyLook).
 */
export const recallScene: ActionDefinition<z.infer<typeof sceneIdParams>> = {
  name: 'recallScene',
  label: 'Recall scene',
  params: sceneIdParams,
  perform(state, p, catalog) {
    const scene = findScene(state, p.sceneId);
    if (!scene) throw new InputError(`no light scene with id '${p.sceneId}'`, { code: 'unknownScene', params: { id: p.sceneId } });
    return recallLooks(state, scene, catalog);
  },
};

const onParams = z.object({ moduleId: z.string(), on: z.boolean() });

/** Switches a module on or off; it keeps its level for switching back on. */
export const setModuleOn: ActionDefinition<z.infer<typeof onParams>> = {
  name: 'setModuleOn',
  label: 'On / off',
  params: onParams,
  perform(state, p) {
    const ref = findModule(state, p.moduleId);
    // Absent means on (scene file version 7): the key is dropped rather than stored as true.
    const { on: _on, ...rest } = ref.module;
    const m = p.on ? rest : { ...rest, on: false };
    return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.map((x, i) => (i === ref.moduleIndex ? m : x)) });
  },
};
