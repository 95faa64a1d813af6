/**
 * The always-valid guarantee holds by construction: the binding, not each
 * definition, refuses an action whose result validate() would reject. A
 * deliberately careless definition (its own isEnabled always true) shows it.
 */
import { describe, expect, it, vi } from 'vitest';
import { z } from 'zod/mini';
import { InputError } from '../../../../src/core/inputError';
import type { ActionDefinition } from '../../../../src/core/model/actions/action';
import { actionDefinitions } from '../../../../src/core/model/actions/actionDefinitions';
import { bindDefinition } from '../../../../src/core/model/actions/bindDefinition';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, only, powered, withPreset } from '../helpers';

const railParams = z.object({ railId: z.string() });

/** Careless: claims it may always run, and packs four 0.6 m linears onto whatever rail it is given. */
const overfill: ActionDefinition<z.infer<typeof railParams>> = {
  name: 'overfill',
  label: 'Overfill',
  params: railParams,
  isEnabled: () => true,
  perform(state, p) {
    const modules = ['x1', 'x2', 'x3', 'x4'].map((id) => ({ id, type: 'linear', beam: 'diffuse', cct: 3000, dimming: 1 }));
    return {
      ...state,
      systems: state.systems.map((s) => ({ ...s, rails: s.rails.map((r) => (r.id === p.railId ? { ...r, modules } : r)) })),
    };
  },
};

describe('the binding refuses what validate() would reject', () => {
  it('a careless definition is refused with the first validation problem as the reason', () => {
    const s = withPreset('single', 1, 1); // a 1.5 m rail
    const rail = only(s).rails[0];
    const action = bindDefinition(overfill, { railId: rail.id }, catalog);
    const broken = action.perform(s);
    const first = validate(broken, catalog)[0];
    expect(first.code).toBe('modules-do-not-fit');
    expect(action.isEnabled(s)).toEqual({ ok: false, reason: `the modules of rail ${rail.id} do not fit its 1.5 m with distribution 'inside-centred'` });
    expect(action.attempt(s)).toEqual({ ok: false, reason: first.message });
  });

  it('an explain hook words the same refusal in the action’s terms', () => {
    const s = withPreset('single', 1, 1);
    const worded = bindDefinition({ ...overfill, explain: (problem) => `rail full (${problem.code})` }, { railId: only(s).rails[0].id }, catalog);
    expect(worded.isEnabled(s)).toEqual({ ok: false, reason: 'rail full (modules-do-not-fit)' });
  });

  it('the same careless definition is enabled where its result is valid', () => {
    let s = withPreset('single', 1, 1);
    s = { ...s, systems: [{ ...only(s), rails: [{ ...only(s).rails[0], length: 3, distribution: 'start' }] }] };
    const action = bindDefinition(overfill, { railId: only(s).rails[0].id }, catalog);
    const outcome = action.attempt(s);
    expect(outcome.ok).toBe(true);
    if (outcome.ok) expect(validate(outcome.next, catalog)).toEqual([]);
  });

  it('geometry is checked too: a careless move outside the room or onto another system', () => {
    const moveParams = z.object({ systemId: z.string(), x: z.number() });
    const slide: ActionDefinition<z.infer<typeof moveParams>> = {
      name: 'slide',
      label: 'Slide',
      params: moveParams,
      isEnabled: () => true,
      perform: (state, p) => ({ ...state, systems: state.systems.map((s) => (s.id === p.systemId ? { ...s, x: p.x } : s)) }),
    };
    const s = withPreset('single', 1, 1); // 8 m wide room
    const id = only(s).id;
    expect(bindDefinition(slide, { systemId: id, x: 7 }, catalog).isEnabled(s)).toEqual({ ok: false, reason: `system ${id} reaches outside the 8 × 6 m room` });
    expect(bindDefinition(slide, { systemId: id, x: 6.5 }, catalog).isEnabled(s)).toBe(true);
  });

  it('an InputError from perform is a refusal; any other error is a bug and propagates', () => {
    const s = withPreset('single', 1, 1);
    const throwing = (error: Error): ActionDefinition<z.infer<typeof railParams>> => ({
      ...overfill,
      perform: () => {
        throw error;
      },
    });
    expect(bindDefinition(throwing(new InputError('no such rail')), { railId: 'r0' }, catalog).isEnabled(s)).toEqual({ ok: false, reason: 'no such rail' });
    expect(() => bindDefinition(throwing(new TypeError('oops')), { railId: 'r0' }, catalog).isEnabled(s)).toThrow('oops');
  });

  it('the definition’s own refusal comes first, and perform is not run for it', () => {
    const perform = vi.fn((state: Configuration) => state);
    const own = bindDefinition({ ...overfill, isEnabled: () => ({ ok: false, reason: 'not today' }), perform }, { railId: 'r0' }, catalog);
    expect(own.isEnabled(withPreset('single', 1, 1))).toEqual({ ok: false, reason: 'not today' });
    expect(perform).not.toHaveBeenCalled();
  });
});

describe('perform runs once', () => {
  it('isEnabled then perform on the same state reuses the performed state', () => {
    const s = powered(withPreset('single', 1, 1));
    const perform = vi.fn(actionDefinitions.addModule.perform);
    const action = bindDefinition({ ...actionDefinitions.addModule, perform }, { railId: only(s).rails[0].id, type: 'spot' }, catalog);
    expect(action.isEnabled(s)).toBe(true);
    const next = action.perform(s);
    expect(perform).toHaveBeenCalledTimes(1);
    expect(action.attempt(s)).toEqual({ ok: true, next });
    // another state is a new decision
    action.isEnabled(next);
    expect(perform).toHaveBeenCalledTimes(2);
  });
});
