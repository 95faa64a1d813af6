/**
 * Placing, moving, rotating, re-hanging and deleting whole systems. Walls, head
 * room and clashes are validate()'s rules, checked on the result where the
 * action is bound; unknown ids and a preset with nowhere to go throw InputError.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import type { Catalog } from '../catalogSchema/catalogSchema';
import type { PresetSpec } from '../catalogSchema/presetSchema';
import { MOUNTINGS, type Configuration } from '../configuration/configuration';
import { normaliseDegrees, rotatePlan, systemBounds } from '../rails/geometry';
import { defaultSuspension, findPresetPlacement, instantiatePreset, type Placement } from './presets';
import { keepFixingsIfValid } from '../rails/fixingRules';
import { replaceSystem, systemIndex, updateSystem } from './lookup';

function findPreset(catalog: Catalog, id: string): PresetSpec {
  const p = catalog.presets.find((x) => x.id === id);
  if (!p) throw new InputError(`unknown preset '${id}'`, { code: 'unknownPreset', params: { id } });
  return p;
}

const placePresetParams = z.object({
  presetId: z.string(),
  /** Anchor (start of the first rail) and heading; omitted: a free spot nearest the room centre is found. */
  x: z.optional(z.number()),
  z: z.optional(z.number()),
  rotation: z.optional(z.number()),
});
type PlacePresetParams = z.infer<typeof placePresetParams>;

/** Where the preset goes and how low it hangs; throws InputError when it cannot go anywhere. */
function presetPlacement(state: Configuration, p: PlacePresetParams, catalog: Catalog): { placement: Placement; suspension: number } {
  const preset = findPreset(catalog, p.presetId);
  if ((p.x === undefined) !== (p.z === undefined)) throw new InputError('give both x and z, or neither', { code: 'giveXAndZ' });
  const suspension = defaultSuspension(catalog, state.room.height);
  if (suspension === null) throw new InputError(`the room is too low: modules must hang at least ${catalog.suspension.minHeightAboveFloor} m above the floor`, { code: 'roomTooLow', params: { min: catalog.suspension.minHeightAboveFloor } });
  if (p.x !== undefined && p.z !== undefined) return { placement: { x: p.x, z: p.z, rotation: p.rotation ?? 0 }, suspension };
  const placement = findPresetPlacement(state, preset, catalog, suspension);
  if (!placement) throw new InputError(`no free space for '${preset.name}' in this room`, { code: 'noFreeSpace', params: { name: preset.name, presetId: preset.id } });
  return { placement, suspension };
}

/** Places a preset at the given anchor, or at the free spot nearest the room centre. */
export const placePreset: ActionDefinition<PlacePresetParams> = {
  name: 'placePreset',
  label: 'Place preset',
  params: placePresetParams,
  perform(state, p, catalog) {
    const where = presetPlacement(state, p, catalog);
    return instantiatePreset(state, findPreset(catalog, p.presetId), catalog, where.placement, where.suspension);
  },
};

const systemIdParams = z.object({ systemId: z.string() });

export const deleteSystem: ActionDefinition<z.infer<typeof systemIdParams>> = {
  name: 'deleteSystem',
  label: 'Delete',
  params: systemIdParams,
  perform(state, p) {
    const i = systemIndex(state, p.systemId);
    return { ...state, systems: state.systems.filter((_, k) => k !== i) };
  },
};

const moveParams = z.object({ systemId: z.string(), x: z.number(), z: z.number() });

/** Moves the anchor (start of the first rail) to (x, z). */
export const moveSystem: ActionDefinition<z.infer<typeof moveParams>> = {
  name: 'moveSystem',
  label: 'Move',
  params: moveParams,
  perform(state, p) {
    return updateSystem(state, p.systemId, { x: p.x, z: p.z });
  },
};

const rotateParams = z.object({ systemId: z.string(), by: z.number() });

/**
 * Turns a system by `by` degrees (counterclockwise seen from above) about the
 * centre of its footprint's bounding box, so it turns in place as users expect.
 */
export const rotateSystem: ActionDefinition<z.infer<typeof rotateParams>> = {
  name: 'rotateSystem',
  label: 'Rotate',
  params: rotateParams,
  perform(state, p, catalog) {
    const i = systemIndex(state, p.systemId);
    const s = state.systems[i];
    const b = systemBounds(s, catalog);
    const c = [(b.minX + b.maxX) / 2, (b.minZ + b.maxZ) / 2] as const;
    const d = rotatePlan([s.x - c[0], s.z - c[1]], p.by);
    return replaceSystem(state, i, { ...s, x: c[0] + d[0], z: c[1] + d[1], rotation: normaliseDegrees(s.rotation + p.by) });
  },
  explain(problem) {
    return quoting(`cannot rotate here: ${problem.message}`, 'cannotRotate', problem);
  },
};

const suspensionParams = z.object({ systemId: z.string(), suspension: z.number() });

export const setSuspension: ActionDefinition<z.infer<typeof suspensionParams>> = {
  name: 'setSuspension',
  label: 'Suspension',
  params: suspensionParams,
  perform(state, p) {
    return updateSystem(state, p.systemId, { suspension: p.suspension });
  },
};

const mountingParams = z.object({ systemId: z.string(), mounting: z.enum(MOUNTINGS) });

/**
 * Hangs a system on suspensions or clips it to the ceiling surface (docs/model.md, "Mounting").
 * Its suspension length is kept for switching back; head room is checked at the height the
 * modules really have (validate()). Moved fixing points stay when they keep the new mounting's
 * spacing and overhang, otherwise they go back to the derived ones (fixingRules.ts).
 */
export const setMounting: ActionDefinition<z.infer<typeof mountingParams>> = {
  name: 'setMounting',
  label: 'Mounting',
  params: mountingParams,
  perform(state, p, catalog) {
    const i = systemIndex(state, p.systemId);
    return replaceSystem(state, i, keepFixingsIfValid({ ...state.systems[i], mounting: p.mounting }, catalog));
  },
};
