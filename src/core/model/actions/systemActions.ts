/** Placing, moving, rotating, re-hanging and deleting whole systems. */
import { z } from 'zod';
import { InputError } from '../../inputError';
import { refuse, type ActionDefinition } from '../action';
import type { Catalog, PresetSpec } from '../catalogSchema';
import type { Configuration } from '../configuration';
import { normaliseDegrees, rotatePlan, systemBounds } from '../geometry';
import { defaultSuspension, findPresetPlacement, instantiatePreset, type Placement } from '../presets';
import { guard, replaceSystem, systemFits, systemIndex } from './lookup';

function findPreset(catalog: Catalog, id: string): PresetSpec {
  const p = catalog.presets.find((x) => x.id === id);
  if (!p) throw new InputError(`unknown preset '${id}'`);
  return p;
}

const placePresetParams = z.object({
  presetId: z.string(),
  /** Anchor (start of the first rail) and heading; omitted: a free spot nearest the room centre is found. */
  x: z.number().optional(),
  z: z.number().optional(),
  rotation: z.number().optional(),
});
type PlacePresetParams = z.infer<typeof placePresetParams>;

function presetPlacement(state: Configuration, p: PlacePresetParams, catalog: Catalog): { placement: Placement; suspension: number } | string {
  const preset = findPreset(catalog, p.presetId);
  const suspension = defaultSuspension(catalog, state.room.height);
  if (suspension === null) return `the room is too low: modules must hang at least ${catalog.suspension.minHeightAboveFloor} m above the floor`;
  if (p.x !== undefined && p.z !== undefined) return { placement: { x: p.x, z: p.z, rotation: p.rotation ?? 0 }, suspension };
  const placement = findPresetPlacement(state, preset, catalog, suspension);
  return placement ? { placement, suspension } : `no free space for '${preset.name}' in this room`;
}

export const placePreset: ActionDefinition<PlacePresetParams> = {
  name: 'placePreset',
  label: 'Place preset',
  params: placePresetParams,
  isEnabled(state, p, catalog) {
    return guard(() => {
      if ((p.x === undefined) !== (p.z === undefined)) return refuse('give both x and z, or neither');
      const where = presetPlacement(state, p, catalog);
      if (typeof where === 'string') return refuse(where);
      return systemFits(placePreset.perform(state, p, catalog), state.systems.length, catalog);
    });
  },
  perform(state, p, catalog) {
    const where = presetPlacement(state, p, catalog);
    if (typeof where === 'string') throw new InputError(where);
    return instantiatePreset(state, findPreset(catalog, p.presetId), catalog, where.placement, where.suspension);
  },
};

const systemIdParams = z.object({ systemId: z.string() });

export const deleteSystem: ActionDefinition<z.infer<typeof systemIdParams>> = {
  name: 'deleteSystem',
  label: 'Delete',
  params: systemIdParams,
  isEnabled(state, p) {
    return guard(() => (systemIndex(state, p.systemId), true));
  },
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
  isEnabled(state, p, catalog) {
    return guard(() => systemFits(moveSystem.perform(state, p, catalog), systemIndex(state, p.systemId), catalog));
  },
  perform(state, p) {
    const i = systemIndex(state, p.systemId);
    return replaceSystem(state, i, { ...state.systems[i], x: p.x, z: p.z });
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
  isEnabled(state, p, catalog) {
    return guard(() => {
      const fit = systemFits(rotateSystem.perform(state, p, catalog), systemIndex(state, p.systemId), catalog);
      return fit === true ? true : refuse(`cannot rotate here: ${fit.reason}`);
    });
  },
  perform(state, p, catalog) {
    const i = systemIndex(state, p.systemId);
    const s = state.systems[i];
    const b = systemBounds(s, catalog);
    const c = [(b.minX + b.maxX) / 2, (b.minZ + b.maxZ) / 2] as const;
    const d = rotatePlan([s.x - c[0], s.z - c[1]], p.by);
    return replaceSystem(state, i, { ...s, x: c[0] + d[0], z: c[1] + d[1], rotation: normaliseDegrees(s.rotation + p.by) });
  },
};

const suspensionParams = z.object({ systemId: z.string(), suspension: z.number() });

export const setSuspension: ActionDefinition<z.infer<typeof suspensionParams>> = {
  name: 'setSuspension',
  label: 'Suspension',
  params: suspensionParams,
  isEnabled(state, p, catalog) {
    return guard(() => systemFits(setSuspension.perform(state, p, catalog), systemIndex(state, p.systemId), catalog));
  },
  perform(state, p) {
    const i = systemIndex(state, p.systemId);
    return replaceSystem(state, i, { ...state.systems[i], suspension: p.suspension });
  },
};
