/**
 * Light modules on a rail: the plus button, removal, type switches and settings.
 * Every change to a rail's module list is re-laid out by the rail's
 * distribution, or keeps the free positions of a freely arranged rail (moveModule); whether the modules still fit (railModuleOffsets() is not null),
 * offered CCTs and beams, and dimming are validate()'s rules, checked on the
 * result where the action is bound. These definitions word the refusals.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { ActionDefinition, CodedReason } from './action';
import { findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration, ModuleInstance, Rail } from '../configuration/configuration';
import { isFreeRail, placeInLargestGap, placementStep, roundOffset, snapOffset } from '../rails/freePositions';
import { railModuleOffsets } from '../rails/geometry';
import { isTunable } from '../modules/dmxPatch';
import { clampAim } from '../modules/aim';
import { newModule } from './presets';
import { beamForType } from '../modules/beamForType';
import { findModule, findRail, replaceRail, takeId, updateModule } from './lookup';

const addParams = z.object({
  railId: z.string(),
  type: z.string(),
  /** Insert before this position in the rail's module list; default: at the end. */
  index: z.optional(z.number().check(z.int(), z.nonnegative())),
});

/** Problems that mean "the modules do not fit": a distribution that cannot hold them, or a free position that breaks a rule. */
export const FIT_CODES: ReadonlySet<string> = new Set(['modules-do-not-fit', 'module-past-end', 'module-overlap']);

/** [start, end) of each module of a rail, from its current layout (the state is valid, so it fits). */
function occupied(rail: Rail, catalog: Catalog, skip = -1): [number, number][] {
  const offsets = railModuleOffsets(rail, catalog);
  if (!offsets) throw new InputError(`the modules of rail ${rail.id} do not fit it now`, { code: 'modulesDoNotFitNow', params: { rail: rail.id } });
  return rail.modules.flatMap((m, i) => (i === skip ? [] : [[offsets[i], offsets[i] + findModuleType(catalog, m.type).length] as [number, number]]));
}

/**
 * The plus button: disabled once the module would not fit (the rail is full). On a freely arranged
 * rail the new module goes, centred and snapped, into the largest free gap (`index` is then
 * ignored: the position decides the order); with no gap long enough it is refused, naming the gap.
 */
export const addModule: ActionDefinition<z.infer<typeof addParams>> = {
  name: 'addModule',
  label: 'Add module',
  params: addParams,
  perform(state, p, catalog) {
    const ref = findRail(state, p.railId);
    const [id, next] = takeId(state, 'm');
    const mods = [...ref.rail.modules];
    if (p.index !== undefined && p.index > mods.length) throw new InputError(`index ${p.index} is beyond the ${mods.length} modules of the rail`, { code: 'moduleIndexBeyond', params: { index: p.index, count: mods.length } });
    const module = newModule(catalog, id, p.type);
    if (!isFreeRail(ref.rail)) {
      mods.splice(p.index ?? mods.length, 0, module);
      return replaceRail(next, ref, { ...ref.rail, modules: mods });
    }
    const length = findModuleType(catalog, p.type).length;
    const { offset } = placeInLargestGap(length, ref.rail.length, occupied(ref.rail, catalog), placementStep(catalog));
    return replaceRail(next, ref, { ...ref.rail, modules: inRailOrder([...mods, { ...module, offset }]) });
  },
  explain(problem, state, p, catalog): string | CodedReason {
    if (!FIT_CODES.has(problem.code)) return problem.message;
    const type = findModuleType(catalog, p.type);
    const { rail } = findRail(state, p.railId);
    if (isFreeRail(rail) && railModuleOffsets(rail, catalog)) {
      const { gap } = placeInLargestGap(type.length, rail.length, occupied(rail, catalog), placementStep(catalog));
      return {
        reason: `no free gap on this rail holds a ${type.name} (${type.length} m): the largest is ${gap} m; move modules apart or choose a distribution`,
        code: 'noFreeGap',
        params: { name: type.name, typeId: type.id, length: type.length, gap },
      };
    }
    return { reason: `no room for another ${type.name} (${type.length} m) on this rail`, code: 'noRoomForModule', params: { name: type.name, typeId: type.id, length: type.length } };
  },
};

/** Free modules sorted by offset (stable), so the list stays in rail order. */
function inRailOrder(mods: readonly ModuleInstance[]): ModuleInstance[] {
  return mods
    .map((m, i) => [m, i] as const)
    .sort((a, b) => a[0].offset! - b[0].offset! || a[1] - b[1])
    .map(([m]) => m);
}

const moveParams = z.object({
  moduleId: z.string(),
  /** Requested start of the module, metres from its rail's start; snapped (freePositions.ts) before the rules are checked. */
  offset: z.number(),
});

/**
 * Moves a module along its rail to a free position (docs/model.md, "Free positions"). The rail
 * becomes freely arranged: its other modules keep the positions their distribution gave them.
 * The requested start snaps to the grid, the rail's ends and the neighbours' ends; a snapped
 * position past an end or over another module is refused (never clamped), with the reason.
 */
export const moveModule: ActionDefinition<z.infer<typeof moveParams>> = {
  name: 'moveModule',
  label: 'Move module',
  params: moveParams,
  perform(state, p, catalog) {
    const ref = findModule(state, p.moduleId);
    const offset = snappedModuleOffset(state, p.moduleId, p.offset, catalog);
    const now = railModuleOffsets(ref.rail, catalog);
    if (!now) throw new InputError(`the modules of rail ${ref.rail.id} do not fit it now`, { code: 'modulesDoNotFitNow', params: { rail: ref.rail.id } });
    const mods = ref.rail.modules.map((m, i) => ({ ...m, offset: i === ref.moduleIndex ? offset : roundOffset(now[i]) }));
    return replaceRail(state, ref, { ...ref.rail, modules: inRailOrder(mods) });
  },
  explain(problem, state, p, catalog): string | CodedReason {
    const ref = findModule(state, p.moduleId);
    // Worded from the rail as it is now; a state whose rail does not fit (never reached through actions) keeps validate()'s words.
    if (!FIT_CODES.has(problem.code) || !railModuleOffsets(ref.rail, catalog)) return problem.message;
    const type = findModuleType(catalog, ref.module.type);
    const offset = snappedModuleOffset(state, p.moduleId, p.offset, catalog);
    const L = ref.rail.length;
    const fmt = (x: number) => String(Math.round(x * 1000) / 1000);
    const named = { name: type.name, typeId: type.id };
    if (offset < 0) {
      const atConnector = ref.railIndex > 0;
      return {
        reason: `${type.name} would start ${fmt(-offset)} m before the ${atConnector ? 'connector at the ' : ''}start of this rail`,
        code: atConnector ? 'moduleBeforeConnector' : 'moduleBeforeStart',
        params: { ...named, by: Number(fmt(-offset)) },
      };
    }
    if (offset + type.length > L) {
      const atConnector = ref.railIndex < ref.system.rails.length - 1;
      return {
        reason: `${type.name} would reach ${fmt(offset + type.length)} m, past the ${atConnector ? 'connector at the ' : ''}end of this ${fmt(L)} m rail`,
        code: atConnector ? 'modulePastConnector' : 'modulePastEnd',
        params: { ...named, reach: Number(fmt(offset + type.length)), length: Number(fmt(L)) },
      };
    }
    const other = occupied(ref.rail, catalog, ref.moduleIndex).findIndex(([a, b]) => offset < b - 1e-9 && offset + type.length > a + 1e-9);
    if (other >= 0) {
      const m = ref.rail.modules.filter((_, i) => i !== ref.moduleIndex)[other];
      const otherType = findModuleType(catalog, m.type);
      return {
        reason: `${type.name} at ${fmt(offset)}–${fmt(offset + type.length)} m would overlap ${otherType.name} ${m.id}`,
        code: 'moduleWouldOverlap',
        params: { ...named, from: Number(fmt(offset)), to: Number(fmt(offset + type.length)), other: otherType.name, otherTypeId: otherType.id, otherId: m.id },
      };
    }
    return problem.message;
  },
};

/** Where moveModule would put a module asked to start at `requested` (the planner's drag previews it). */
export function snappedModuleOffset(state: Configuration, moduleId: string, requested: number, catalog: Catalog): number {
  const ref = findModule(state, moduleId);
  const length = findModuleType(catalog, ref.module.type).length;
  return snapOffset(requested, length, ref.rail.length, occupied(ref.rail, catalog, ref.moduleIndex), placementStep(catalog));
}

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
    if (problem.code !== 'modules-do-not-fit') return problem.message;
    const distribution = findModule(state, p.moduleId).rail.distribution;
    return { reason: `the other modules would not fit '${distribution}' without it`, code: 'othersWouldNotFit', params: { distribution } };
  },
};

const typeParams = z.object({ moduleId: z.string(), type: z.string() });

/** Switches a module's type; only to types that fit without clashing. Keeps the beam (or the nearest beam angle, beamForType.ts) and the CCT where the new type offers them, the DMX patch (without a CCT channel when the new type has one CCT), and the aim within the new type's limits (none for a fixed type). */
export const setModuleType: ActionDefinition<z.infer<typeof typeParams>> = {
  name: 'setModuleType',
  label: 'Module type',
  params: typeParams,
  perform(state, p, catalog) {
    const { module } = findModule(state, p.moduleId);
    const type = findModuleType(catalog, p.type);
    const beam = beamForType(
      catalog.moduleTypes.find((t) => t.id === module.type),
      module.beam,
      type,
    );
    const cct = type.ccts.includes(module.cct) ? module.cct : type.defaultCct;
    // A type with one CCT has no CCT channel: the patch keeps its level channels and shrinks, so it never meets a neighbour.
    const dmx = module.dmx?.cct && !isTunable(type) ? { ...module.dmx, cct: false } : module.dmx;
    // An aim carries over within the new type's limits (clamped, docs/aiming.md); a fixed type points straight down.
    const aim = module.aim && type.adjustable ? clampAim(module.aim, type.adjustable) : undefined;
    const { aim: _dropped, ...rest } = module;
    void _dropped;
    const ref = findModule(state, p.moduleId);
    const next: ModuleInstance = { ...rest, type: type.id, beam, cct, ...(dmx ? { dmx } : {}), ...(aim ? { aim } : {}) };
    return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.map((x, i) => (i === ref.moduleIndex ? next : x)) });
  },
  explain(problem, _state, p, catalog) {
    if (!FIT_CODES.has(problem.code)) return problem.message;
    const type = findModuleType(catalog, p.type);
    return { reason: `a ${type.name} (${type.length} m) does not fit here without clashing`, code: 'typeDoesNotFit', params: { name: type.name, typeId: type.id, length: type.length } };
  },
};

/** A definition that sets fields of one module; whether the values are offered is validate()'s rule. */
function moduleSetting<P extends { moduleId: string }>(name: string, label: string, params: z.ZodMiniType<P>, patch: (p: P) => Partial<ModuleInstance>): ActionDefinition<P> {
  return { name, label, params, perform: (state, p) => updateModule(state, p.moduleId, patch(p)) };
}

const cctParams = z.object({ moduleId: z.string(), cct: z.number() });

export const setModuleCct: ActionDefinition<z.infer<typeof cctParams>> = {
  ...moduleSetting('setModuleCct', 'Colour temperature', cctParams, (p) => ({ cct: p.cct })),
  explain(problem, state, p, catalog) {
    if (problem.code !== 'cct') return problem.message;
    const type = findModuleType(catalog, findModule(state, p.moduleId).module.type);
    return { reason: `${type.name} comes in ${type.ccts.join(', ')} K only`, code: 'cctOnly', params: { name: type.name, typeId: type.id, ccts: type.ccts.join(', ') } };
  },
};

export const setModuleBeam = moduleSetting('setModuleBeam', 'Beam', z.object({ moduleId: z.string(), beam: z.string() }), (p) => ({ beam: p.beam }));

export const setModuleDimming = moduleSetting('setModuleDimming', 'Dimming', z.object({ moduleId: z.string(), dimming: z.number() }), (p) => ({ dimming: p.dimming }));
