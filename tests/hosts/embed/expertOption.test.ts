/**
 * The embed option `expert` (docs/embedding.md, "Expert tools"): who decides whether the DMX live
 * control, the Radiance download and the photometric data notes show.
 */
import { describe, expect, it } from 'vitest';
import { checkExpert, EmbedOptionsError } from '../../../src/hosts/embed/mountLuxbox';
import { createUiStore } from '../../../src/core/store/uiStore';

describe('options.expert', () => {
  it('default and false: hidden, no switch; true: shown, no switch; "switch": the user decides, off at first', () => {
    expect(checkExpert(undefined, false)).toEqual({ expert: false, expertSwitch: false });
    expect(checkExpert(false, true)).toEqual({ expert: false, expertSwitch: false });
    expect(checkExpert(true, false)).toEqual({ expert: true, expertSwitch: false });
    // No localStorage in this process: nothing remembered, so off.
    expect(checkExpert('switch', true)).toEqual({ expert: false, expertSwitch: true });
  });

  it('anything else is refused, naming the option', () => {
    for (const bad of ['yes', 1, null, { on: true }]) {
      expect(() => checkExpert(bad, false)).toThrow(EmbedOptionsError);
      expect(() => checkExpert(bad, false)).toThrow(/^options\.expert: .* is not true, false or 'switch'$/);
    }
  });

  it('a UI store starts with the expert tools off and no switch', () => {
    const ui = createUiStore();
    expect(ui.getState().expert).toBe(false);
    expect(ui.getState().expertSwitch).toBe(false);
  });
});
