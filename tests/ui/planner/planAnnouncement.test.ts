import { describe, expect, test } from 'vitest';
import { defaultCatalog } from '../../../src/core/catalog/defaultCatalog';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { createConfiguratorStore, type ConfiguratorState } from '../../../src/core/store/createConfiguratorStore';
import { createFormat } from '../../../src/ui/i18n/createFormat';
import { createTranslator } from '../../../src/ui/i18n/createTranslator';
import type { Language } from '../../../src/ui/i18n/languages';
import de from '../../../src/ui/i18n/messages/de/index';
import en from '../../../src/ui/i18n/messages/en/index';
import type { MessageTree } from '../../../src/ui/i18n/messageTypes';
import { announcement, describeSelection, type AnnouncedState, type AnnounceContext } from '../../../src/ui/planner/planAnnouncement';

function context(tree: Partial<MessageTree>, locale: string, language: Language): AnnounceContext {
  const format = createFormat(locale, 'EUR');
  return { catalog: defaultCatalog, t: createTranslator(tree, locale, (x) => format.number(x)), format, language };
}
const EN = context(en, 'en-GB', 'en');
const DE = context(de, 'de-CH', 'de');
const state = (s: ConfiguratorState): AnnouncedState => ({ config: s.config, selection: s.selection, past: s.history.past.length, future: s.history.future.length });

/** The default 5 × 4 × 2.8 m room with the L-corner preset: rails of 2 m and 1.5 m, three modules each (default-catalog.json). */
function cornerL() {
  const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
  expect(store.getState().dispatch('placePreset', { presetId: 'corner-l' }).ok).toBe(true);
  return store;
}

describe('plan announcements for screen readers', () => {
  test('a module: its place on its rail, type, colour temperature and level', () => {
    const store = cornerL();
    const { config } = store.getState();
    const rail = config.systems[0].rails[0];
    const m = rail.modules[2];
    const text = describeSelection(config, { kind: 'module', id: m.id }, EN)!;
    expect(text.startsWith(`Module 3 of ${rail.modules.length} on rail 1, `)).toBe(true);
    expect(text).toContain(`${m.cct} K`);
    expect(text.endsWith('100%')).toBe(true);
    // German texts, Swiss formatting; one system, so no system number.
    expect(describeSelection(config, { kind: 'module', id: m.id }, DE)!.startsWith(`Modul 3 von ${rail.modules.length} auf Schiene 1, `)).toBe(true);
  });

  test('rail and system: counts with plurals, length in the locale', () => {
    const store = cornerL();
    const { config } = store.getState();
    const s = config.systems[0];
    const modules = s.rails.reduce((n, r) => n + r.modules.length, 0);
    expect(describeSelection(config, { kind: 'system', id: s.id }, EN)).toBe(`System 1, 2 rails, ${modules} modules`);
    expect(describeSelection(config, { kind: 'rail', id: s.rails[1].id }, EN)).toBe(`Rail 2 of system 1, 1.50 m, ${s.rails[1].modules.length} modules`);
    expect(describeSelection(config, { kind: 'rail', id: s.rails[1].id }, DE)).toBe(`Schiene 2 von System 1, 1.50 m, ${s.rails[1].modules.length} Module`);
    expect(describeSelection(config, { kind: 'module', id: 'nope' }, EN)).toBeNull();
  });

  test('selecting, changing, undoing and redoing are each announced', () => {
    const store = cornerL();
    const api = store.getState();
    const m = api.config.systems[0].rails[0].modules[0];
    const s0 = state(store.getState());
    store.getState().select({ kind: 'module', id: m.id });
    const s1 = state(store.getState());
    expect(announcement(s0, s1, EN)).toMatch(/^Module 1 of \d on rail 1, .* selected$/);

    expect(store.getState().dispatch('setModuleDimming', { moduleId: m.id, dimming: 0.5 }).ok).toBe(true);
    const s2 = state(store.getState());
    expect(announcement(s1, s2, EN)).toMatch(/^Changed: Module 1 of \d on rail 1, .*, 50%$/);

    store.getState().undo();
    const s3 = state(store.getState());
    expect(announcement(s2, s3, EN)).toMatch(/^Undone\. Module 1 of \d on rail 1, .*, 100%$/);
    store.getState().redo();
    expect(announcement(s3, state(store.getState()), EN)).toMatch(/^Redone\. .*50%$/);

    store.getState().select(null);
    expect(announcement(s3, state(store.getState()), EN)).toMatch(/^(Redone\. )?Room: 1 lighting system, 6 modules, 0 objects$/);
    const cleared = state(store.getState());
    expect(announcement(cleared, cleared, EN)).toBeNull();
  });

  test('nothing selected after a change: what the room now holds', () => {
    const store = createConfiguratorStore({ catalog: defaultCatalog, initial: createConfiguration() });
    const before = state(store.getState());
    store.getState().dispatch('placePreset', { presetId: 'single' });
    store.getState().select(null);
    expect(announcement(before, state(store.getState()), EN)).toBe('Room: 1 lighting system, 3 modules, 0 objects');
    expect(announcement(before, state(store.getState()), DE)).toBe('Raum: 1 Lichtsystem, 3 Module, 0 Objekte');
  });
});
