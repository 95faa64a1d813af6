/**
 * Aiming adjustable modules (docs/aiming.md). Both actions clamp and snap to the type's limits
 * (clampAim), so an aim is always valid: dragging past a limit stops the head there, as the
 * real swivel does. The only refusal is a fixed (non-adjustable) type, with the reason.
 */
import { z } from 'zod/mini';
import { InputError } from '../../inputError';
import type { ActionDefinition } from './action';
import { aimToward, clampAim } from '../modules/aim';
import { findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import { type ModuleTypeSpec } from '../catalogSchema/moduleTypeSchema';
import type { Configuration } from '../configuration/configuration';
import { modulePlacements } from '../rails/geometry';
import { moduleHeight } from '../rails/suspensionPoints';
import { findModule, updateModule } from './lookup';

function adjustableType(state: Configuration, moduleId: string, catalog: Catalog): ModuleTypeSpec & { adjustable: NonNullable<ModuleTypeSpec['adjustable']> } {
  const type = findModuleType(catalog, findModule(state, moduleId).module.type);
  if (!type.adjustable) throw new InputError(`${type.name} is fixed: it cannot be aimed`, { code: 'aimFixed', params: { name: type.name, typeId: type.id } });
  return type as ModuleTypeSpec & { adjustable: NonNullable<ModuleTypeSpec['adjustable']> };
}

const degrees = z.number().check(z.refine(Number.isFinite, 'must be a finite number of degrees'));
const setAimParams = z.object({ moduleId: z.string(), aim: z.object({ rotation: degrees, tilt: degrees }) });

/** Sets a module's aim; out-of-range values are clamped and snapped to the nearest stop (never refused). */
export const setAim: ActionDefinition<z.infer<typeof setAimParams>> = {
  name: 'setAim',
  label: 'Aim',
  params: setAimParams,
  perform(state, p, catalog) {
    const type = adjustableType(state, p.moduleId, catalog);
    return updateModule(state, p.moduleId, { aim: clampAim(p.aim, type.adjustable) });
  },
};

const metres = z.number().check(z.refine(Number.isFinite, 'must be a finite number of metres'));
const point = z.tuple([metres, metres, metres]);
const aimAtParams = z.object({ moduleId: z.string(), point });

/** Where a module's photometric centre is, world metres. */
export function modulePosition(state: Configuration, moduleId: string, catalog: Catalog): [number, number, number] {
  const { system } = findModule(state, moduleId);
  const placement = modulePlacements(system, catalog).find((q) => q.moduleId === moduleId);
  if (!placement) throw new InputError(`module ${moduleId} has no place on its rail now`, { code: 'moduleNoPlace', params: { id: moduleId } });
  return [placement.centre[0], moduleHeight(system, state.room, catalog), placement.centre[1]];
}

/**
 * The aim aimAt gives: the axis through the world point, then the nearest reachable aim (clampAim).
 * Beyond the tilt range the head stops at the limit in the same plan direction, which is the
 * nearest reachable direction on the sphere; in the rotation gap it stops at the nearer end at
 * the same tilt, likewise nearest since, at fixed tilt, the angle between two axes grows with
 * their difference in plan direction.
 */
export function aimAtPoint(state: Configuration, moduleId: string, target: readonly [number, number, number], catalog: Catalog) {
  const type = adjustableType(state, moduleId, catalog);
  const { module, system } = findModule(state, moduleId);
  const placement = modulePlacements(system, catalog).find((q) => q.moduleId === moduleId)!;
  const from = modulePosition(state, moduleId, catalog);
  const raw = aimToward(from, [target[0], target[1], target[2]], placement.heading, module.aim?.rotation ?? 0);
  if (!raw) throw new InputError(`the point is the module's own position: no direction to aim at`, { code: 'aimAtOwnPosition' });
  return clampAim(raw, type.adjustable);
}

/** Turns a module so its axis goes through a world point (metres), within its limits: the nearest reachable aim. */
export const aimAt: ActionDefinition<z.infer<typeof aimAtParams>> = {
  name: 'aimAt',
  label: 'Aim at',
  params: aimAtParams,
  perform(state, p, catalog) {
    return updateModule(state, p.moduleId, { aim: aimAtPoint(state, p.moduleId, p.point, catalog) });
  },
};
