/**
 * Light modules on a rail: the plus button, removal, type switches and settings.
 * Every change to a rail's module list is re-laid out by the rail's
 * distribution, so "fits" is the one test: layoutModules() is not null.
 */
import { z } from 'zod';
import { InputError } from '../../inputError';
import { refuse, type ActionDefinition } from '../action';
import { findBeam, findModuleType, type Catalog } from '../catalogSchema';
import type { ModuleInstance, Rail } from '../configuration';
import { layoutModules } from '../distribution';
import { newModule } from '../presets';
import { findModule, findRail, guard, replaceRail, takeId } from './lookup';

function fits(modules: readonly ModuleInstance[], rail: Rail, catalog: Catalog): boolean {
  return layoutModules(modules.map((m) => findModuleType(catalog, m.type).length), rail.length, rail.distribution) !== null;
}

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
  isEnabled(state, p, catalog) {
    return guard(() => {
      const { rail } = findRail(state, p.railId);
      if (p.index !== undefined && p.index > rail.modules.length) return refuse(`index ${p.index} is beyond the ${rail.modules.length} modules of the rail`);
      const type = findModuleType(catalog, p.type);
      const modules = addModule.perform(state, p, catalog);
      const after = findRail(modules, p.railId).rail;
      return fits(after.modules, after, catalog) ? true : refuse(`no room for another ${type.name} (${type.length} m) on this rail`);
    });
  },
  perform(state, p, catalog) {
    const ref = findRail(state, p.railId);
    const [id, next] = takeId(state, 'm');
    const mods = [...ref.rail.modules];
    if (p.index !== undefined && p.index > mods.length) throw new InputError(`index ${p.index} is beyond the ${mods.length} modules of the rail`);
    mods.splice(p.index ?? mods.length, 0, newModule(catalog, id, p.type));
    return replaceRail(next, ref, { ...ref.rail, modules: mods });
  },
};

const moduleIdParams = z.object({ moduleId: z.string() });

export const removeModule: ActionDefinition<z.infer<typeof moduleIdParams>> = {
  name: 'removeModule',
  label: 'Remove module',
  params: moduleIdParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      const { rail, moduleIndex } = findModule(state, p.moduleId);
      const rest = rail.modules.filter((_, i) => i !== moduleIndex);
      // With outside-centred spacing and mixed lengths, taking one out can make neighbours collide.
      return fits(rest, rail, catalog) ? true : refuse(`the other modules would not fit '${rail.distribution}' without it`);
    });
  },
  perform(state, p) {
    const ref = findModule(state, p.moduleId);
    return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.filter((_, i) => i !== ref.moduleIndex) });
  },
};

const typeParams = z.object({ moduleId: z.string(), type: z.string() });

/** Switches a module's type; only to types that fit without clashing. Keeps the CCT where the new type offers it. */
export const setModuleType: ActionDefinition<z.infer<typeof typeParams>> = {
  name: 'setModuleType',
  label: 'Module type',
  params: typeParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      const type = findModuleType(catalog, p.type);
      const after = findRail(setModuleType.perform(state, p, catalog), findModule(state, p.moduleId).rail.id).rail;
      return fits(after.modules, after, catalog) ? true : refuse(`a ${type.name} (${type.length} m) does not fit here without clashing`);
    });
  },
  perform(state, p, catalog) {
    const ref = findModule(state, p.moduleId);
    const type = findModuleType(catalog, p.type);
    const cct = type.ccts.includes(ref.module.cct) ? ref.module.cct : type.defaultCct;
    const m: ModuleInstance = { ...ref.module, type: type.id, beam: type.defaultBeam, cct };
    return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.map((x, i) => (i === ref.moduleIndex ? m : x)) });
  },
};

function updateModule(state: Parameters<typeof findModule>[0], moduleId: string, patch: Partial<ModuleInstance>) {
  const ref = findModule(state, moduleId);
  const m = { ...ref.module, ...patch };
  return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.map((x, i) => (i === ref.moduleIndex ? m : x)) });
}

const cctParams = z.object({ moduleId: z.string(), cct: z.number() });

export const setModuleCct: ActionDefinition<z.infer<typeof cctParams>> = {
  name: 'setModuleCct',
  label: 'Colour temperature',
  params: cctParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      const type = findModuleType(catalog, findModule(state, p.moduleId).module.type);
      return type.ccts.includes(p.cct) ? true : refuse(`${type.name} comes in ${type.ccts.join(', ')} K only`);
    });
  },
  perform(state, p) {
    return updateModule(state, p.moduleId, { cct: p.cct });
  },
};

const beamParams = z.object({ moduleId: z.string(), beam: z.string() });

export const setModuleBeam: ActionDefinition<z.infer<typeof beamParams>> = {
  name: 'setModuleBeam',
  label: 'Beam',
  params: beamParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      findBeam(findModuleType(catalog, findModule(state, p.moduleId).module.type), p.beam);
      return true;
    });
  },
  perform(state, p) {
    return updateModule(state, p.moduleId, { beam: p.beam });
  },
};

const dimmingParams = z.object({ moduleId: z.string(), dimming: z.number() });

export const setModuleDimming: ActionDefinition<z.infer<typeof dimmingParams>> = {
  name: 'setModuleDimming',
  label: 'Dimming',
  params: dimmingParams,
  isEnabled(state, p) {
    return guard(() => {
      findModule(state, p.moduleId);
      return p.dimming >= 0 && p.dimming <= 1 ? true : refuse('dimming must be between 0 and 1');
    });
  },
  perform(state, p) {
    return updateModule(state, p.moduleId, { dimming: p.dimming });
  },
};
