/**
 * The DMX patch (docs/live-control.md): auto-patch, one module's patch, clearing
 * it all. Like every action these are undoable and always valid: channels
 * shared with another module or running past 512 are validate()'s rules
 * (dmx-overlap, dmx-range), checked on the result where the action is bound;
 * these definitions word the refusals.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import type { Catalog } from '../catalogSchema/catalogSchema';
import { findModuleType } from '../catalogSchema/catalogSchema';
import type { Configuration, ModuleInstance } from '../configuration/configuration';
import { DMX_CHANNELS, DMX_UNIVERSE_MAX, DMX_UNIVERSE_MIN, isTunable, modulesInOrder, patchWidth } from '../modules/dmxPatch';
import { type DmxPatch } from '../configuration/configuration';
import { findModule } from './lookup';

const resolution = z.union([z.literal(8), z.literal(16)]);
const patchSchema = z.object({ universe: z.number(), address: z.number(), resolution, cct: z.boolean() });

/** The configuration with every module's patch set by `patchOf` (undefined: unpatched); systems without a change stay the same objects. */
function mapPatches(config: Configuration, patchOf: (m: ModuleInstance) => DmxPatch | undefined): Configuration {
  let changed = false;
  const systems = config.systems.map((s) => {
    let sChanged = false;
    const rails = s.rails.map((r) => {
      let rChanged = false;
      const modules = r.modules.map((m) => {
        const dmx = patchOf(m);
        if (dmx === m.dmx) return m;
        rChanged = true;
        const { dmx: _old, ...rest } = m;
        return dmx ? { ...rest, dmx } : rest;
      });
      if (!rChanged) return r;
      sChanged = true;
      return { ...r, modules };
    });
    if (!sChanged) return s;
    changed = true;
    return { ...s, rails };
  });
  return changed ? { ...config, systems } : config;
}

const moduleParams = z.object({ moduleId: z.string(), patch: z.nullable(patchSchema) });

/** Patches one module (or unpatches it with `patch: null`). */
export const setModulePatch: ActionDefinition<z.infer<typeof moduleParams>> = {
  name: 'setModulePatch',
  label: 'DMX patch',
  params: moduleParams,
  perform(state, p) {
    findModule(state, p.moduleId); // unknown id: InputError
    return mapPatches(state, (m) => (m.id === p.moduleId ? (p.patch ?? undefined) : m.dmx));
  },
  explain(problem) {
    return problem.code === 'dmx-overlap' || problem.code === 'dmx-range' ? problem.message : quoting(`cannot patch: ${problem.message}`, 'cannotPatch', problem);
  },
};

const autoParams = z.object({
  universe: z.number().check(z.int(), z.gte(DMX_UNIVERSE_MIN), z.lte(DMX_UNIVERSE_MAX)),
  /** First channel of the first module, 1..512. */
  address: z.number().check(z.int(), z.gte(1), z.lte(DMX_CHANNELS)),
  resolution,
  /** A CCT channel for every tunable module. */
  cct: z.boolean(),
});

/**
 * Patches every module, in module order (system, rail, position on the rail),
 * to consecutive channels from (universe, address). A module never straddles
 * two universes: one that would run past 512 starts the next universe at 1.
 * Replaces any earlier patch, so nothing is left to overlap.
 */
export function autoPatchPlan(config: Configuration, catalog: Catalog, p: z.infer<typeof autoParams>): Map<string, DmxPatch> {
  const plan = new Map<string, DmxPatch>();
  let universe = p.universe;
  let address = p.address;
  for (const { module } of modulesInOrder(config)) {
    const patch = { resolution: p.resolution, cct: p.cct && isTunable(findModuleType(catalog, module.type)) };
    if (address + patchWidth(patch) - 1 > DMX_CHANNELS) {
      universe++;
      address = 1;
    }
    if (universe > DMX_UNIVERSE_MAX) throw new InputError(`the modules do not fit below universe ${DMX_UNIVERSE_MAX}`, { code: 'patchBeyondUniverses', params: { max: DMX_UNIVERSE_MAX } });
    plan.set(module.id, { universe, address, ...patch });
    address += patchWidth(patch);
  }
  return plan;
}

export const autoPatch: ActionDefinition<z.infer<typeof autoParams>> = {
  name: 'autoPatch',
  label: 'Auto-patch',
  params: autoParams,
  perform(state, p, catalog) {
    const plan = autoPatchPlan(state, catalog, p);
    return mapPatches(state, (m) => {
      const next = plan.get(m.id);
      const old = m.dmx;
      // Keep the module object when its patch is unchanged: re-running auto-patch touches nothing.
      return old && next && old.universe === next.universe && old.address === next.address && old.resolution === next.resolution && old.cct === next.cct ? old : next;
    });
  },
};

/** Unpatches every module (nothing patched: no change, like auto-patch of an empty room; the UI greys the button). */
const noParams = z.object({});

export const clearPatch: ActionDefinition<z.infer<typeof noParams>> = {
  name: 'clearPatch',
  label: 'Clear patch',
  params: noParams,
  perform(state) {
    return mapPatches(state, () => undefined);
  },
};
