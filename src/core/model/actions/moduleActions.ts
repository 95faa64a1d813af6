/**
 * Light modules on a rail: the plus button, removal, type switches and settings.
 * Every change to a rail's module list is re-laid out by the rail's
 * distribution; whether the modules still fit (railModuleOffsets() is not null),
 * offered CCTs and beams, and dimming are validate()'s rules, checked on the
 * result where the action is bound. These definitions word the refusals.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import type { ActionDefinition } from '../action';
import { findModuleType } from '../catalogSchema';
import type { ModuleInstance } from '../configuration';
import { isTunable } from '../dmxPatch';
import { newModule } from '../presets';
import { findModule, findRail, replaceRail, takeId, updateModule } from './lookup';

const addParams = z.object({
  railId: z.string(),
  type: z.string(),
  /** Insert before this position in the rail's module list; default: at the end. */
  index: z.number().int().nonnegative().optional(),
});

/** The plus button: disabled once the module would not fit (the rail is full). */
export const addModule: ActionDefinition<z.infer<typeof addParams>> = {
  name: 'addModule',
  label: 'Add module',
  params: addParams,
  perform(state, p, catalog) {
    const ref = findRail(state, p.railId);
    const [id, next] = takeId(state, 'm');
    const mods = [...ref.rail.modules];
    if (p.index !== undefined && p.index > mods.length) throw new InputError(`index ${p.index} is beyond the ${mods.length} modules of the rail`);
    mods.splice(p.index ?? mods.length, 0, newModule(catalog, id, p.type));
    return replaceRail(next, ref, { ...ref.rail, modules: mods });
  },
  explain(problem, _state, p, catalog) {
    if (problem.code !== 'modules-do-not-fit') return problem.message;
    const type = findModuleType(catalog, p.type);
    return `no room for another ${type.name} (${type.length} m) on this rail`;
  },
};

const moduleIdParams = z.object({ moduleId: z.string() });

export const removeModule: ActionDefinition<z.infer<typeof moduleIdParams>> = {
  name: 'removeModule',
  label: 'Remove module',
  params: moduleIdParams,
  perform(state, p) {
    const ref = findModule(state, p.moduleId);
    return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.filter((_, i) => i !== ref.moduleIndex) });
  },
  explain(problem, state, p) {
    // With outside-centred spacing and mixed lengths, taking one out can make neighbours collide.
    return problem.code === 'modules-do-not-fit' ? `the other modules would not fit '${findModule(state, p.moduleId).rail.distribution}' without it` : problem.message;
  },
};

const typeParams = z.object({ moduleId: z.string(), type: z.string() });

/** Switches a module's type; only to types that fit without clashing. Keeps the CCT where the new type offers it, and the DMX patch (without a CCT channel when the new type has one CCT). */
export const setModuleType: ActionDefinition<z.infer<typeof typeParams>> = {
  name: 'setModuleType',
  label: 'Module type',
  params: typeParams,
  perform(state, p, catalog) {
    const { module } = findModule(state, p.moduleId);
    const type = findModuleType(catalog, p.type);
    const cct = type.ccts.includes(module.cct) ? module.cct : type.defaultCct;
    // A type with one CCT has no CCT channel: the patch keeps its level channels and shrinks, so it never meets a neighbour.
    const dmx = module.dmx?.cct && !isTunable(type) ? { ...module.dmx, cct: false } : module.dmx;
    return updateModule(state, p.moduleId, { type: type.id, beam: type.defaultBeam, cct, ...(dmx ? { dmx } : {}) });
  },
  explain(problem, _state, p, catalog) {
    if (problem.code !== 'modules-do-not-fit') return problem.message;
    const type = findModuleType(catalog, p.type);
    return `a ${type.name} (${type.length} m) does not fit here without clashing`;
  },
};

/** A definition that sets fields of one module; whether the values are offered is validate()'s rule. */
function moduleSetting<P extends { moduleId: string }>(name: string, label: string, params: z.ZodType<P>, patch: (p: P) => Partial<ModuleInstance>): ActionDefinition<P> {
  return { name, label, params, perform: (state, p) => updateModule(state, p.moduleId, patch(p)) };
}

const cctParams = z.object({ moduleId: z.string(), cct: z.number() });

export const setModuleCct: ActionDefinition<z.infer<typeof cctParams>> = {
  ...moduleSetting('setModuleCct', 'Colour temperature', cctParams, (p) => ({ cct: p.cct })),
  explain(problem, state, p, catalog) {
    if (problem.code !== 'cct') return problem.message;
    const type = findModuleType(catalog, findModule(state, p.moduleId).module.type);
    return `${type.name} comes in ${type.ccts.join(', ')} K only`;
  },
};

export const setModuleBeam = moduleSetting('setModuleBeam', 'Beam', z.object({ moduleId: z.string(), beam: z.string() }), (p) => ({ beam: p.beam }));

export const setModuleDimming = moduleSetting('setModuleDimming', 'Dimming', z.object({ moduleId: z.string(), dimming: z.number() }), (p) => ({ dimming: p.dimming }));
