/**
 * Light scenes (cues): their rules, what recording and recalling do, and how a module's state
 * becomes a look (docs/light-scenes.md, docs/model.md "Light scenes").
 */
import { keyed } from '../configuration/coding';
import { findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration, LightScene, ModuleInstance, ModuleLook } from '../configuration/configuration';
import type { Problem } from '../configuration/problem';

/** Fade times a scene may have, seconds (issue #12: 0–30 s). */
export const FADE_LIMITS = { min: 0, max: 30 } as const;

/** Longest scene name, characters (the scene file's limit). */
export const SCENE_NAME_MAX = 200;

/** Every module of a configuration, in plan order. */
export function allModules(config: Configuration): ModuleInstance[] {
  return config.systems.flatMap((s) => s.rails.flatMap((r) => r.modules));
}

/** The look of a module as it is now. */
export function lookOf(m: ModuleInstance): ModuleLook {
  return { on: m.on !== false, level: m.dimming, cct: m.cct, ...(m.filter !== undefined ? { filter: m.filter } : {}) };
}

/** Every module's look (recordScene, updateScene). */
export function looksOf(config: Configuration): Record<string, ModuleLook> {
  return Object.fromEntries(allModules(config).map((m) => [m.id, lookOf(m)]));
}

/** Names compare trimmed and case-insensitively: "Evening" and "evening " are the same scene to a user. */
export function sameSceneName(a: string, b: string): boolean {
  return a.trim().toLocaleLowerCase('en') === b.trim().toLocaleLowerCase('en');
}

export function findScene(config: Configuration, id: string): LightScene | undefined {
  return config.lightScenes?.find((s) => s.id === id);
}

export function sceneByName(config: Configuration, name: string): LightScene | undefined {
  return config.lightScenes?.find((s) => sameSceneName(s.name, name));
}

/**
 * A module with a look applied. The rule for a look the module can no longer take (its type was
 * switched since the scene was recorded): a stored CCT the type does not offer leaves the
 * module's CCT as it is, and a stored filter the catalog no longer lists, or that the type cannot
 * hold (no `filterHolder`), leaves the module's filter as it is; on/off and level always apply. So a recall never produces an invalid module
 * and never changes what the look cannot describe.
 */
export function applyLook(m: ModuleInstance, look: ModuleLook, catalog: Catalog): ModuleInstance {
  const type = findModuleType(catalog, m.type);
  const cct = type.ccts.includes(look.cct) ? look.cct : m.cct;
  // No filter in the look: none. A filter the catalog no longer lists or the type cannot hold: the module keeps its own.
  const takes = (id: string) => type.filterHolder === true && (catalog.filters ?? []).some((f) => f.id === id);
  const filter = look.filter === undefined ? undefined : takes(look.filter) ? look.filter : m.filter;
  const next: ModuleInstance = { ...m, dimming: look.level, cct, on: look.on, filter };
  // Absent fields mean on and unfiltered (scene file version 7): written that way.
  const { on, filter: f, ...rest } = next;
  return { ...rest, ...(on ? {} : { on: false }), ...(f !== undefined ? { filter: f } : {}) };
}

/** The configuration with a scene's looks applied; modules the scene does not list keep their state. */
export function recallLooks(config: Configuration, scene: LightScene, catalog: Catalog): Configuration {
  return {
    ...config,
    systems: config.systems.map((s) => ({
      ...s,
      rails: s.rails.map((r) => ({ ...r, modules: r.modules.map((m) => (scene.looks[m.id] ? applyLook(m, scene.looks[m.id], catalog) : m)) })),
    })),
  };
}

/**
 * Looks of modules that no longer exist removed from every scene (the same object when there
 * are none): run on every action's result (bindDefinition.ts), so removing a module, a rail or a
 * system removes it from every scene, and validate() can insist that looks name real modules.
 */
export function pruneLooks(config: Configuration): Configuration {
  const scenes = config.lightScenes;
  if (!scenes || scenes.length === 0) return config;
  const ids = new Set(allModules(config).map((m) => m.id));
  let changed = false;
  const next = scenes.map((s) => {
    const keys = Object.keys(s.looks);
    if (keys.every((k) => ids.has(k))) return s;
    changed = true;
    return { ...s, looks: Object.fromEntries(keys.filter((k) => ids.has(k)).map((k) => [k, s.looks[k]])) };
  });
  return changed ? { ...config, lightScenes: next } : config;
}

/** validate()'s light-scene rules: names present and unique, fade in range, looks of existing modules with levels in 0..1. */
export function lightSceneProblems(config: Configuration): Problem[] {
  const out: Problem[] = [];
  const scenes = config.lightScenes ?? [];
  const ids = new Set(allModules(config).map((m) => m.id));
  scenes.forEach((s, i) => {
    const at = `lightScenes[${i}]`;
    if (s.name.trim() === '') out.push(keyed({ code: 'scene-name', path: `${at}.name`, message: `light scene ${s.id} needs a name` }, 'sceneNeedsName', { id: s.id }));
    else if (s.name.length > SCENE_NAME_MAX) out.push(keyed({ code: 'scene-name', path: `${at}.name`, message: `light scene name is longer than ${SCENE_NAME_MAX} characters` }, 'sceneNameLong', { max: SCENE_NAME_MAX }));
    const twin = scenes.findIndex((o, k) => k < i && sameSceneName(o.name, s.name));
    if (twin >= 0 && s.name.trim() !== '') out.push(keyed({ code: 'scene-name-taken', path: `${at}.name`, message: `a light scene named '${scenes[twin].name}' exists already` }, 'sceneNameTaken', { name: scenes[twin].name }));
    if (!Number.isFinite(s.fade) || s.fade < FADE_LIMITS.min || s.fade > FADE_LIMITS.max)
      out.push(
        keyed({ code: 'scene-fade', path: `${at}.fade`, message: `fade time must be between ${FADE_LIMITS.min} and ${FADE_LIMITS.max} s (got ${s.fade})` }, 'sceneFadeRange', { min: FADE_LIMITS.min, max: FADE_LIMITS.max, value: s.fade }),
      );
    for (const [moduleId, look] of Object.entries(s.looks)) {
      const lp = `${at}.looks.${moduleId}`;
      if (!ids.has(moduleId)) out.push(keyed({ code: 'scene-module', path: lp, message: `light scene '${s.name}' has a look for module ${moduleId}, which does not exist` }, 'sceneModuleMissing', { name: s.name, id: moduleId }));
      if (!Number.isFinite(look.level) || look.level < 0 || look.level > 1)
        out.push(keyed({ code: 'scene-level', path: `${lp}.level`, message: `level must be between 0 and 1 (got ${look.level})` }, 'sceneLevelRange', { value: look.level }));
      if (!Number.isFinite(look.cct) || look.cct < 1000 || look.cct > 20000)
        out.push(keyed({ code: 'scene-cct', path: `${lp}.cct`, message: `colour temperature must be between 1000 and 20000 K (got ${look.cct})` }, 'sceneCctRange', { min: '1000', max: '20000', value: String(look.cct) }));
    }
  });
  return out;
}
