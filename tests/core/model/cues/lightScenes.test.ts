/**
 * Light scenes (docs/light-scenes.md): the scene actions with undo, validate()'s rules, recall's
 * rule for looks a module can no longer take, scene files and share links (version 7, and a
 * version 6 file with scenes refused), on/off and dim to warm in the lighting scene.
 */
import { describe, expect, it } from 'vitest';
import { parseCatalog } from '../../../../src/core/model/catalogSchema/catalogSchema';
import type { Configuration } from '../../../../src/core/model/configuration/configuration';
import { cctAtLevel } from '../../../../src/core/model/catalogSchema/dimmingCurve';
import { allModules } from '../../../../src/core/model/cues/lightScenes';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import { createConfiguratorStore } from '../../../../src/core/store/createConfiguratorStore';
import { cctToLinearRgb } from '../../../../src/core/photometry/cct';
import { catalog, enabled, run, withPreset } from '../helpers';

const modules = (c: Configuration) => allModules(c);
const refusal = (state: Configuration, name: string, params: unknown) => {
  const e = enabled(state, name, params);
  return e === true ? null : e.reason;
};

/** The "single" preset with its first module dimmed and its second switched off. */
function twoLooks() {
  let s = withPreset('single', 1, 1);
  const [a, b] = modules(s);
  const full = run(s, 'recordScene', { name: 'Full' });
  s = run(full, 'setModuleDimming', { moduleId: a.id, dimming: 0.25 });
  s = run(s, 'setModuleOn', { moduleId: b.id, on: false });
  s = run(s, 'setModuleCct', { moduleId: a.id, cct: 2700 });
  const evening = run(s, 'recordScene', { name: 'Evening', fade: 5 });
  return { a, b, evening };
}

describe('scene actions', () => {
  it('record stores every module’s on, level, CCT; recall applies them; a module not in the look keeps its state', () => {
    const { a, b, evening } = twoLooks();
    const [full, ev] = evening.lightScenes!;
    expect(full.looks[a.id]).toEqual({ on: true, level: a.dimming, cct: a.cct });
    expect(ev).toMatchObject({ name: 'Evening', fade: 5 });
    expect(ev.looks[a.id]).toEqual({ on: true, level: 0.25, cct: 2700 });
    expect(ev.looks[b.id]).toEqual({ on: false, level: b.dimming, cct: b.cct });
    const back = run(evening, 'recallScene', { sceneId: full.id });
    const mb = modules(back).find((m) => m.id === b.id)!;
    expect(mb.on).toBeUndefined(); // absent = on
    expect(modules(back).find((m) => m.id === a.id)).toMatchObject({ dimming: a.dimming, cct: a.cct });
    // A look that lists only module a leaves module b alone.
    const partial: Configuration = { ...evening, lightScenes: [{ ...full, looks: { [a.id]: full.looks[a.id] } }, ev] };
    const kept = run(partial, 'recallScene', { sceneId: full.id });
    expect(modules(kept).find((m) => m.id === b.id)!.on).toBe(false);
  });

  it('update, rename, reorder, fade, delete; unique names, fade range and unknown ids are refused with reasons', () => {
    const { a, evening } = twoLooks();
    const [full, ev] = evening.lightScenes!;
    expect(refusal(evening, 'renameScene', { sceneId: ev.id, name: ' full ' })).toBe("a light scene named 'Full' exists already");
    expect(refusal(evening, 'recordScene', { name: '  ' })).toMatch(/needs a name/);
    // Coded for the scene panel's translation (i18n area 'scenes').
    expect(enabled(evening, 'renameScene', { sceneId: ev.id, name: 'FULL' })).toMatchObject({ code: 'nameTaken', params: { name: 'Full' } });
    expect(enabled(evening, 'renameScene', { sceneId: ev.id, name: 'EVENING' })).toBe(true);
    expect(enabled(evening, 'setSceneFade', { sceneId: ev.id, fade: 40 })).toMatchObject({ code: 'fadeRange', params: { min: 0, max: 30 } });
    expect(enabled(evening, 'reorderScene', { sceneId: ev.id, index: 5 })).toMatchObject({ code: 'positionOutside', params: { position: 6, count: 2 } });
    expect(refusal(evening, 'setSceneFade', { sceneId: ev.id, fade: 31 })).toBe('a fade takes 0 to 30 s');
    expect(refusal(evening, 'setSceneFade', { sceneId: ev.id, fade: -0.1 })).toBe('a fade takes 0 to 30 s');
    expect(refusal(evening, 'recallScene', { sceneId: 'q999' })).toBe("no light scene with id 'q999'");
    expect(refusal(evening, 'reorderScene', { sceneId: ev.id, index: 2 })).toBe('position 3 is outside the list of 2 scenes');
    let s = run(evening, 'setSceneFade', { sceneId: ev.id, fade: 30 });
    s = run(s, 'renameScene', { sceneId: ev.id, name: 'Dinner' });
    s = run(s, 'reorderScene', { sceneId: ev.id, index: 0 });
    expect(s.lightScenes!.map((x) => [x.name, x.fade])).toEqual([
      ['Dinner', 30],
      ['Full', 3],
    ]);
    s = run(s, 'setModuleDimming', { moduleId: a.id, dimming: 0.5 });
    s = run(s, 'updateScene', { sceneId: full.id });
    expect(s.lightScenes![1].looks[a.id].level).toBe(0.5);
    s = run(s, 'deleteScene', { sceneId: ev.id });
    s = run(s, 'deleteScene', { sceneId: full.id });
    expect(s.lightScenes).toBeUndefined();
  });

  it('removing a module removes its look from every scene, by the action; validate() refuses a look of a missing module', () => {
    const { b, evening } = twoLooks();
    const s = run(evening, 'removeModule', { moduleId: b.id });
    for (const scene of s.lightScenes!) expect(Object.keys(scene.looks)).not.toContain(b.id);
    expect(validate(s, catalog)).toEqual([]);
    const forged: Configuration = { ...s, lightScenes: evening.lightScenes };
    expect(validate(forged, catalog).map((p) => p.code)).toContain('scene-module');
    // Deleting the whole system empties the looks, the scenes stay.
    const none = run(evening, 'deleteSystem', { systemId: evening.systems[0].id });
    expect(none.lightScenes!.map((x) => Object.keys(x.looks).length)).toEqual([0, 0]);
  });

  it('recall: a stored CCT the module’s new type does not offer leaves the module’s CCT as it is', () => {
    const { a, evening } = twoLooks();
    const full = evening.lightScenes![0];
    expect(full.looks[a.id].cct).toBe(3000);
    // The warm-dim spot comes in 2700 K only; the look says 3000 K.
    const switched = run(evening, 'setModuleType', { moduleId: a.id, type: 'spot-warmdim' });
    expect(modules(switched).find((m) => m.id === a.id)!.cct).toBe(2700);
    const recalled = run(switched, 'recallScene', { sceneId: full.id });
    expect(modules(recalled).find((m) => m.id === a.id)).toMatchObject({ type: 'spot-warmdim', cct: 2700, dimming: a.dimming });
  });

  it('store: every scene action is one undo step', () => {
    const { a, evening } = twoLooks();
    const store = createConfiguratorStore({ catalog, initial: evening });
    const st = () => store.getState();
    expect(st().dispatch('recallScene', { sceneId: evening.lightScenes![0].id })).toEqual({ ok: true });
    expect(modules(st().config).find((m) => m.id === a.id)!.dimming).toBe(a.dimming);
    expect(st().undo()).toBe(true);
    expect(st().config).toBe(evening);
    expect(st().dispatch('deleteScene', { sceneId: evening.lightScenes![1].id })).toEqual({ ok: true });
    expect(st().config.lightScenes).toHaveLength(1);
    st().undo();
    expect(st().config.lightScenes).toHaveLength(2);
  });
});

describe('files and links', () => {
  it('scenes and on/off round-trip through a version 7 scene file and a share link', () => {
    const { evening } = twoLooks();
    expect(deserializeConfiguration(serializeConfiguration(evening, catalog), catalog)).toEqual(evening);
    expect(decodeShareString(encodeShareString(evening, catalog), catalog)).toEqual(evening);
  });

  it('a version 6 file with light scenes is refused, naming the field and the version', () => {
    const doc = JSON.parse(serializeConfiguration(withPreset('single', 1, 1), catalog));
    doc.version = 6;
    doc.configuration.lightScenes = [];
    expect(() => deserializeConfiguration(JSON.stringify(doc), catalog)).toThrow('configuration.lightScenes: needs "version": 7 (this file says version 6)');
  });
});

describe('the light of a look', () => {
  it('a switched-off module stays in the lighting scene, dimmed to 0', () => {
    const { b, evening } = twoLooks();
    const scene = toLightingScene(evening, catalog);
    expect(scene.luminaires.find((l) => l.id === b.id)).toMatchObject({ dimming: 0 });
    expect(scene.luminaires).toHaveLength(modules(evening).length);
  });

  it('dim to warm: 2700 K at full, 1800 K at 1 % and below, mired linear in log10(level) between', () => {
    const type = catalog.moduleTypes.find((t) => t.id === 'spot-warmdim')!;
    expect(type.dimming).toMatchObject({ curve: 'dim-to-warm', cctFull: 2700, cctMin: 1800, levelMin: 0.01 });
    expect(cctAtLevel(type.dimming, 1, 2700)).toBeCloseTo(2700, 9);
    expect(cctAtLevel(type.dimming, 0.01, 2700)).toBeCloseTo(1800, 9);
    expect(cctAtLevel(type.dimming, 0, 2700)).toBeCloseTo(1800, 9);
    // level 0.1: u = 1/2, mired = (10⁶/2700 + 10⁶/1800)/2 = 462.963 → 2160 K (by hand).
    expect(cctAtLevel(type.dimming, 0.1, 2700)).toBeCloseTo(2160, 6);
    expect(cctAtLevel({ curve: 'constant-cct' }, 0.1, 3000)).toBe(3000);
    expect(cctAtLevel(undefined, 0.1, 3000)).toBe(3000);
  });

  it('the colour handed to the baker follows the level of a dim-to-warm module; a constant-CCT module keeps its colour', () => {
    let s = withPreset('single', 1, 1);
    const [a, b] = modules(s);
    s = run(s, 'setModuleType', { moduleId: a.id, type: 'spot-warmdim' });
    s = run(s, 'setModuleDimming', { moduleId: a.id, dimming: 0.1 });
    s = run(s, 'setModuleDimming', { moduleId: b.id, dimming: 0.1 });
    const lum = toLightingScene(s, catalog).luminaires;
    const expected = cctToLinearRgb(2160);
    lum.find((l) => l.id === a.id)!.color!.forEach((v, k) => expect(v).toBeCloseTo(expected[k], 9));
    expect(lum.find((l) => l.id === b.id)!.color).toEqual(cctToLinearRgb(b.cct));
  });

  it('a catalog dim-to-warm type must offer exactly its cctFull, and cctMin must be below it', () => {
    const spot = catalog.moduleTypes.find((t) => t.id === 'spot-warmdim')!;
    const bad = { ...catalog, moduleTypes: [{ ...spot, dimming: { ...spot.dimming!, cctMin: 2700 } }] };
    expect(() => parseCatalog(bad)).toThrow(/moduleTypes\[0\]\.dimming\.cctMin: 2700 K must be below cctFull \(2700 K\)/);
    const twoCcts = { ...catalog, moduleTypes: [{ ...spot, ccts: [2700, 3000] }] };
    expect(() => parseCatalog(twoCcts)).toThrow(/moduleTypes\[0\]\.ccts: a dim-to-warm type offers exactly its cctFull \(2700 K\)/);
  });
});
