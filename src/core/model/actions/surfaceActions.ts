/**
 * The room's surface finishes: one reflectance for a surface, or the same for
 * all four walls at once. Refused only for values outside [0, MAX_REFLECTANCE]
 * per channel (validate()'s rule on the result), so any finish from the list (or
 * any sane custom value) is always accepted; geometry is never affected.
 */
import { z } from 'zod/mini';
import type { ActionDefinition } from './action';
import { quoting } from '../configuration/coding';
import type { Reflectance, SurfaceName } from '../lightingScene/lightingScene';
import { SURFACE_TARGETS, targetSurfaces } from '../lightingScene/reflectance';

const setReflectanceParams = z.object({
  surface: z.enum(SURFACE_TARGETS),
  /** Grey (one number) or linear RGB, each channel in [0, 0.95]. */
  value: z.union([z.number(), z.tuple([z.number(), z.number(), z.number()])]),
});

export const setReflectance: ActionDefinition<z.infer<typeof setReflectanceParams>> = {
  name: 'setReflectance',
  label: 'Surface finish',
  params: setReflectanceParams,
  perform(state, p) {
    const reflectance: Record<SurfaceName, Reflectance> = { ...state.room.reflectance };
    // Copy RGB arrays so the configuration never shares a mutable array with the caller.
    for (const s of targetSurfaces(p.surface)) reflectance[s] = typeof p.value === 'number' ? p.value : [p.value[0], p.value[1], p.value[2]];
    // All walls at once on a drawn room: its walls' own finishes give way to the one chosen.
    const own = state.room.shape;
    if (p.surface === 'walls' && own?.wallReflectance) {
      const { wallReflectance: _given, ...shape } = own;
      return { ...state, room: { ...state.room, reflectance, shape } };
    }
    return { ...state, room: { ...state.room, reflectance } };
  },
  explain(problem, _state, p) {
    // Name the surface as the user chose it ("walls"), not the first wall validate() reports.
    return problem.code === 'reflectance' ? quoting(`${p.surface}: ${problem.message}`, 'surfaceProblem', problem, { surface: p.surface }) : problem.message;
  },
};
