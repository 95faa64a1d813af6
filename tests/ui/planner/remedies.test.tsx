/**
 * Remedies and first-run suggestions in the planner (issue 27): the remedy's words and price in the
 * UI language, the gate offering it and running its steps as one undoable change, and the first-run
 * card (markup, rendered with react-dom/server).
 */
import { renderToStaticMarkup } from 'react-dom/server';
import { describe, expect, it } from 'vitest';
import { attemptAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { remedyFor } from '../../../src/core/model/guidance/remedy';
import { suggestedPresets } from '../../../src/core/model/guidance/suggestedPresets';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';
import { createI18n } from '../../../src/ui/i18n/createI18n';
import { createActionGate } from '../../../src/ui/planner/actionGate';
import { createUiStore } from '../../../src/core/store/uiStore';
import { FirstRunHint } from '../../../src/ui/planner/FirstRunHint';
import { remedyText } from '../../../src/ui/planner/remedyText';
import { remedyOffer } from '../../../src/ui/planner/remedyOffer';
import { catalog } from '../../core/model/helpers';

const room = { width: 5, depth: 4, height: 2.8 };
function lCorner(): Configuration {
  const o = attemptAction(createConfiguration(room), 'placePreset', { presetId: 'corner-l' }, catalog);
  if (!o.ok) throw new Error(o.reason);
  return o.next;
}

describe('remedy wording', () => {
  it('says the driver and the price difference in English and German', async () => {
    const config = lCorner();
    const remedy = remedyFor(config, 'addModule', { railId: config.systems[0].rails[0].id, type: 'spot' }, catalog)!;
    const en = createI18n({ locale: 'en-GB', currency: 'EUR' }).getSnapshot();
    expect(remedyText(en.t, en.format, en.language, remedy)).toBe('Use the 321.6 W driver (+€28.00)');
    const de = createI18n({ locale: 'de-DE', currency: 'EUR' });
    await de.ready;
    const s = de.getSnapshot();
    expect(remedyText(s.t, s.format, s.language, remedy)).toBe('321,6-W-Treiber verwenden (+28,00\u00a0€)');
  });

  it('joins a rail change and a driver change', () => {
    const config = lCorner();
    const rail = config.systems[0].rails[1];
    const remedy = remedyFor(config, 'addModule', { railId: rail.id, type: 'updown' }, catalog)!;
    expect(remedy.steps.length).toBeGreaterThan(1);
    const en = createI18n({ locale: 'en-GB', currency: 'EUR' }).getSnapshot();
    expect(remedyText(en.t, en.format, en.language, remedy)).toMatch(/^Lengthen rail 2 to [\d.]+ m, then .*\(\+€[\d.]+\)$/);
  });
});

describe('the tip offers and runs a remedy (remedyOffer)', () => {
  const en = createI18n({ locale: 'en-GB', currency: 'EUR' }).getSnapshot();
  it('one tap makes the refused + work, one undo takes it back', () => {
    const store = createConfiguratorStore({ catalog, initial: lCorner() });
    const config = store.getState().config;
    const railId = config.systems[0].rails[0].id;
    const gate = createActionGate(
      config,
      catalog,
      (n, p) => store.getState().dispatch(n, p),
      () => {},
    );
    expect(gate.reason('addModule', { railId, type: 'spot' })).toMatch(/driver is full/);
    const offer = remedyOffer(store, 'addModule', { railId, type: 'spot' }, en)!;
    expect(offer.label).toBe('Use the 321.6 W driver (+€28.00)');
    offer.run();
    expect(store.getState().config.systems[0].feeds[0].driver).toBe('hlg-320h-48');
    expect(store.getState().dispatch('addModule', { railId, type: 'spot' })).toEqual({ ok: true });
    store.getState().undo();
    store.getState().undo();
    expect(store.getState().config).toBe(config);
  });
  it('a rail change and a driver change are one undo step', () => {
    const store = createConfiguratorStore({ catalog, initial: lCorner() });
    const config = store.getState().config;
    const params = { railId: config.systems[0].rails[1].id, type: 'updown' };
    remedyOffer(store, 'addModule', params, en)!.run();
    expect(store.getState().dispatch('addModule', params)).toEqual({ ok: true });
    store.getState().undo();
    store.getState().undo();
    expect(store.getState().config).toBe(config);
  });
  it('offers nothing for an enabled action', () => {
    const placed = attemptAction(createConfiguration(room), 'placePreset', { presetId: 'single' }, catalog);
    if (!placed.ok) throw new Error();
    const store = createConfiguratorStore({ catalog, initial: placed.next });
    expect(remedyOffer(store, 'addModule', { railId: placed.next.systems[0].rails[0].id, type: 'spot' }, en)).toBeNull();
  });
});

describe('first run', () => {
  it('suggests the presets that cover the room best; a 2 × 2 m room gets only what fits', () => {
    expect(suggestedPresets(room, catalog).map((s) => s.presetId)).toEqual(['snake', 'u-shape', 'corner-l']);
    expect(suggestedPresets({ width: 2, depth: 2, height: 2.8 }, catalog).map((s) => s.presetId)).toEqual(['single']);
    expect(suggestedPresets(room, catalog, 3, ['single', 'long-line', 'corner-l']).map((s) => s.presetId)).toEqual(['single', 'corner-l']);
  });
  it('renders one button per suggestion, the shop’s list, or none', () => {
    const gate = createActionGate(
      createConfiguration(room),
      catalog,
      () => {},
      () => {},
    );
    const html = (options?: { presets?: string[] | false }) => renderToStaticMarkup(<FirstRunHint room={room} catalog={catalog} gate={gate} options={options} onPlaced={() => {}} ui={createUiStore()} />);
    expect(html().match(/data-testid="first-run-[a-z-]+"/g)).toEqual(['data-testid="first-run-snake"', 'data-testid="first-run-u-shape"', 'data-testid="first-run-corner-l"', 'data-testid="first-run-all"']);
    expect(html({ presets: ['corner-l'] })).toContain('Place L corner');
    expect(html({ presets: false })).not.toContain('first-run-snake');
    expect(html()).toContain('Start with a layout');
  });
});
