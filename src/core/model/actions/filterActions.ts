/**
 * Putting a colour filter (gel) in front of a module, or taking it out (docs/colour-filters.md).
 * Whether the filter exists in the catalog and the module type has a holder is validate()'s rule
 * (moduleFilter.ts), checked on the result where the action is bound; the refusal is its message.
 * A filter changes only the module's colour and lumens, so the 3D view relights, never rebakes.
 */
import { z } from 'zod/mini';
import type { ActionDefinition } from './action';
import type { ModuleInstance } from '../configuration/configuration';
import { findModule, replaceRail } from './lookup';

const filterParams = z.object({ moduleId: z.string(), filter: z.nullable(z.string()) });

export const setModuleFilter: ActionDefinition<z.infer<typeof filterParams>> = {
  name: 'setModuleFilter',
  label: 'Colour filter',
  params: filterParams,
  perform(state, p) {
    const ref = findModule(state, p.moduleId);
    // No filter: the field is left out (absent = none), not set to undefined, so scene files stay clean.
    const { filter: _old, ...rest } = ref.module;
    void _old;
    const next: ModuleInstance = p.filter === null ? rest : { ...rest, filter: p.filter };
    return replaceRail(state, ref, { ...ref.rail, modules: ref.rail.modules.map((m, i) => (i === ref.moduleIndex ? next : m)) });
  },
};
