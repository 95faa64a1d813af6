import { describe, expect, it, vi } from 'vitest';
import { defaultCatalog as catalog } from '../../../src/core/catalog/defaultCatalog';
import { actionDefinitions, checkAction } from '../../../src/core/model/actions/actionDefinitions';
import { billOfMaterials } from '../../../src/core/model/power/billOfMaterials';
import { createConfiguration } from '../../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration } from '../../../src/core/model/files/sceneFile';
import { createConfiguratorStore } from '../../../src/core/store/createConfiguratorStore';

const fresh = () => createConfiguratorStore({ catalog, initial: createConfiguration({ width: 6, depth: 5, height: 3 }) });

describe('configurator store', () => {
  it('dispatches enabled actions, returns refusals, undoes and redoes every step', () => {
    const store = fresh();
    const seen: number[] = [];
    store.subscribe((s) => seen.push(s.config.systems.length));
    expect(store.getState().dispatch('placePreset', { presetId: 'single' })).toEqual({ ok: true });
    const sys = store.getState().config.systems[0];
    const rail = sys.rails[0].id;
    // Power for ten 43 W spots (issue 11): the largest driver at both ends, so the rail's length is the limit.
    expect(store.getState().dispatch('setFeedDriver', { feedId: sys.feeds[0].id, driver: 'hlg-320h-48' })).toEqual({ ok: true });
    expect(store.getState().dispatch('addFeed', { systemId: sys.id, at: 'end', driver: 'hlg-320h-48' })).toEqual({ ok: true });
    let adds = 0;
    while (store.getState().dispatch('addModule', { railId: rail, type: 'spot' }).ok) adds++;
    expect(adds).toBe(7);
    expect(store.getState().isEnabled('addModule', { railId: rail, type: 'spot' })).toEqual({ ok: false, reason: expect.stringMatching(/no room/) });
    const snapshots = [store.getState().config];
    expect(store.getState().canUndo).toBe(true);
    for (let i = 0; i < 10; i++) {
      expect(store.getState().undo()).toBe(true);
      snapshots.push(store.getState().config);
    }
    expect(store.getState().config.systems).toEqual([]);
    expect(store.getState().undo()).toBe(false);
    for (let i = 0; i < 10; i++) store.getState().redo();
    expect(store.getState().config).toBe(snapshots[0]);
    expect(store.getState().canRedo).toBe(false);
    expect(seen.length).toBeGreaterThan(10);
  });
  it('bad names and params come back as refusals, not exceptions', () => {
    const s = fresh().getState();
    expect(s.dispatch('explode', {})).toEqual({ ok: false, reason: expect.stringMatching(/unknown action 'explode'/) });
    expect(s.dispatch('moveSystem', { systemId: 's1', x: 'left' })).toEqual({ ok: false, reason: expect.stringMatching(/moveSystem: x: /) });
  });
  it('lists every action with its enablement for given params', () => {
    const store = fresh();
    store.getState().dispatch('placePreset', { presetId: 'single' });
    const m = store.getState().config.systems[0].rails[0].modules[0].id;
    const list = store.getState().listActions({ setModuleCct: { moduleId: m, cct: 4000 }, setModuleBeam: { moduleId: m, beam: 'nope' } });
    expect(list.map((a) => a.name)).toContain('placePreset');
    expect(list.find((a) => a.name === 'setModuleCct')!.enabled).toBe(true);
    expect(list.find((a) => a.name === 'setModuleBeam')!.enabled).toMatchObject({ ok: false });
  });
  it('keeps selection outside history and drops it when the item disappears', () => {
    const store = fresh();
    store.getState().dispatch('placePreset', { presetId: 'single' });
    const id = store.getState().config.systems[0].id;
    store.getState().select({ kind: 'system', id });
    expect(store.getState().selection).toEqual({ kind: 'system', id });
    store.getState().dispatch('deleteSystem', { systemId: id });
    expect(store.getState().selection).toBeNull();
    store.getState().undo();
    expect(store.getState().selection).toBeNull();
    store.getState().select({ kind: 'module', id: 'ghost' });
    expect(store.getState().selection).toBeNull();
  });
  it('loads a scene file (undoable) and prices follow the configuration', () => {
    const a = fresh();
    a.getState().dispatch('placePreset', { presetId: 'corner-l' });
    const text = serializeConfiguration(a.getState().config, catalog);
    const b = fresh();
    expect(b.getState().load(deserializeConfiguration(text, catalog))).toEqual({ ok: true });
    expect(billOfMaterials(b.getState().config, catalog).total).toBe(billOfMaterials(a.getState().config, catalog).total);
    b.getState().undo();
    expect(b.getState().config.systems).toEqual([]);
    expect(b.getState().load({ ...a.getState().config, room: { ...a.getState().config.room, width: 0.2 } })).toMatchObject({ ok: false });
  });

  it('performs an action once when the UI asks isEnabled and then dispatches', () => {
    const store = fresh();
    store.getState().dispatch('placePreset', { presetId: 'single' });
    store.getState().dispatch('addFeed', { systemId: store.getState().config.systems[0].id, at: 'end', driver: 'hlg-320h-48' });
    const params = { railId: store.getState().config.systems[0].rails[0].id, type: 'spot' };
    const spy = vi.spyOn(actionDefinitions.addModule, 'perform');
    try {
      expect(store.getState().isEnabled('addModule', params)).toBe(true);
      expect(store.getState().dispatch('addModule', params)).toEqual({ ok: true });
      expect(spy).toHaveBeenCalledTimes(1);
      // the new state is asked afresh; the planner asks through checkAction, then dispatches
      expect(checkAction(store.getState().config, 'addModule', params, catalog)).toBe(true);
      expect(spy).toHaveBeenCalledTimes(2);
      expect(store.getState().dispatch('addModule', params)).toEqual({ ok: true });
      expect(spy).toHaveBeenCalledTimes(2);
    } finally {
      spy.mockRestore();
    }
  });
});
