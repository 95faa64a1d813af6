import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { createConfiguratorStore } from '../../../../src/core/store/createConfiguratorStore';
import { checkAction } from '../../../../src/core/model/actions/actionDefinitions';
import { findModuleType } from '../../../../src/core/model/catalogSchema/catalogSchema';
import { createConfiguration, type Configuration, type ModuleInstance } from '../../../../src/core/model/configuration/configuration';
import { cctChannelValue, cctFromChannel, decodeLevel, DMX_CHANNELS, formatPatchRange, modulesInOrder, patchWidth } from '../../../../src/core/model/modules/dmxPatch';
import { type DmxPatch } from '../../../../src/core/model/configuration/configuration';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SCENE_FILE_VERSION } from '../../../../src/core/model/files/sceneFileSchema';
import { SceneFileError } from '../../../../src/core/model/files/sceneFileError';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { validate } from '../../../../src/core/model/validation/validate';
import { catalog, enabled, run, withPreset } from '../helpers';

const modules = (c: Configuration): ModuleInstance[] => modulesInOrder(c).map((x) => x.module);
/** Two systems: 'corner-l' (6 modules, tunable spots, floods and washers) placed first, then 'single' (3 spots). */
const twoSystems = () => run(withPreset('corner-l', 1, 4), 'placePreset', { presetId: 'single', x: 5, z: 5 });
const p = (universe: number, address: number, resolution: 8 | 16 = 8, cct = false): DmxPatch => ({ universe, address, resolution, cct });

describe('DMX patch: channels', () => {
  it('takes one or two level channels and an optional CCT channel', () => {
    expect(patchWidth(p(1, 1, 8))).toBe(1);
    expect(patchWidth(p(1, 1, 16))).toBe(2);
    expect(patchWidth(p(1, 1, 16, true))).toBe(3);
    expect(formatPatchRange(p(2, 5, 16, true))).toBe('2/5–7');
    expect(formatPatchRange(p(2, 5))).toBe('2/5');
  });
  it('decodes 8-bit and 16-bit levels (coarse at the address, fine after it)', () => {
    const ch = new Uint8Array(DMX_CHANNELS);
    ch[9] = 128; // channel 10
    ch[10] = 64; // channel 11
    expect(decodeLevel(ch, { address: 10, resolution: 8 })).toBeCloseTo(128 / 255, 12);
    expect(decodeLevel(ch, { address: 10, resolution: 16 })).toBeCloseTo((128 * 256 + 64) / 65535, 12);
    ch[9] = 255;
    ch[10] = 255;
    expect(decodeLevel(ch, { address: 10, resolution: 16 })).toBe(1);
    expect(decodeLevel(ch, { address: 12, resolution: 16 })).toBe(0);
    // The fine byte resolves what the coarse one cannot: 0x00FF is 255 steps above 0x0000 but below 1/255.
    expect(decodeLevel([0, 255], { address: 1, resolution: 16 })).toBeCloseTo(255 / 65535, 12);
    expect(decodeLevel([0, 255], { address: 1, resolution: 16 })).toBeLessThan(1 / 255);
    // Short frames and junk read as 0; values beyond a byte are clamped.
    expect(decodeLevel([], { address: 512, resolution: 16 })).toBe(0);
    expect(decodeLevel([300, Number.NaN], { address: 1, resolution: 16 })).toBeCloseTo((255 * 256) / 65535, 12);
  });
  it('maps the CCT channel linearly over the type range, continuously', () => {
    const spot = findModuleType(catalog, 'spot'); // 2700, 3000, 4000 K
    expect(cctFromChannel(0, spot)).toBe(2700);
    expect(cctFromChannel(255, spot)).toBe(4000);
    expect(cctFromChannel(51, spot)).toBeCloseTo(2700 + (51 / 255) * 1300, 9); // 2960 K: between offered CCTs, not snapped
    expect(cctFromChannel(-4, spot)).toBe(2700);
    const ch = [0, 0, 0, 200];
    expect(cctChannelValue(ch, p(1, 2, 16, true))).toBe(200);
    expect(cctChannelValue(ch, p(1, 3, 8, true))).toBe(200);
    expect(cctChannelValue(ch, p(1, 2, 16, false))).toBeNull();
  });
});

describe('DMX patch: actions', () => {
  it('auto-patch goes in module order (system, rail, position) to consecutive channels', () => {
    const c = run(twoSystems(), 'autoPatch', { universe: 1, address: 10, resolution: 16, cct: true });
    const list = modules(c);
    expect(list.length).toBe(9);
    let address = 10;
    for (const m of list) {
      const tunable = findModuleType(catalog, m.type).ccts.length > 1;
      expect(m.dmx).toEqual({ universe: 1, address, resolution: 16, cct: tunable });
      address += tunable ? 3 : 2;
    }
    // The order is the configuration's: first system's rails in chain order, modules from each rail's start.
    const ids = c.systems.flatMap((s) => s.rails.flatMap((r) => r.modules.map((m) => m.id)));
    expect(list.map((m) => m.id)).toEqual(ids);
    expect(validate(c, catalog)).toEqual([]);
    // 8-bit without CCT: one channel each.
    const d = run(c, 'autoPatch', { universe: 3, address: 1, resolution: 8, cct: false });
    expect(modules(d).map((m) => m.dmx!.address)).toEqual([1, 2, 3, 4, 5, 6, 7, 8, 9]);
  });
  it('auto-patch starts the next universe rather than split a module', () => {
    const c = run(twoSystems(), 'autoPatch', { universe: 1, address: 508, resolution: 16, cct: false });
    expect(modules(c).map((m) => formatPatchRange(m.dmx!))).toEqual(['1/508–509', '1/510–511', '2/1–2', '2/3–4', '2/5–6', '2/7–8', '2/9–10', '2/11–12', '2/13–14']);
    expect(checkAction(withPreset('single', 1, 1), 'autoPatch', { universe: 1, address: 513, resolution: 8, cct: false }, catalog)).toMatchObject({ ok: false, reason: expect.stringMatching(/address/) });
    // An empty room: nothing to patch, nothing changes (refusals are for invalid results only).
    expect(run(createConfiguration(), 'autoPatch', { universe: 1, address: 1, resolution: 8, cct: false })).toEqual(createConfiguration());
  });
  it('refuses an address that overlaps another module or runs past 512, with the reason', () => {
    const c = run(twoSystems(), 'autoPatch', { universe: 1, address: 1, resolution: 16, cct: false }); // 1–2, 3–4, …
    const [a, b, , , , , g] = modules(c);
    const overlap = enabled(c, 'setModulePatch', { moduleId: a.id, patch: p(1, 4, 8) });
    // Named on the later module in module order, with both ranges.
    expect(overlap).toEqual({ ok: false, reason: `DMX 1/3–4 of module ${b.id} overlaps module ${a.id} (1/4)` });
    // The module in the other system: the patch rule spans systems.
    expect(enabled(c, 'setModulePatch', { moduleId: g.id, patch: p(1, 2, 8) })).toMatchObject({ ok: false, reason: expect.stringMatching(/overlaps module/) });
    expect(enabled(c, 'setModulePatch', { moduleId: a.id, patch: p(1, 512, 16) })).toEqual({ ok: false, reason: 'channels 512–513 would run past 512' });
    expect(enabled(c, 'setModulePatch', { moduleId: a.id, patch: p(1, 0, 8) })).toMatchObject({ ok: false, reason: expect.stringMatching(/address must be an integer in 1\.\.512/) });
    expect(enabled(c, 'setModulePatch', { moduleId: a.id, patch: p(0, 20, 8) })).toMatchObject({ ok: false, reason: 'DMX universe must be an integer in 1..63999 (got 0)' });
    expect(enabled(c, 'setModulePatch', { moduleId: 'm999', patch: p(1, 20, 8) })).toMatchObject({ ok: false, reason: "no module with id 'm999'" });
    // Same address in another universe, the last channel, and unpatching are fine.
    expect(enabled(c, 'setModulePatch', { moduleId: a.id, patch: p(2, 3, 16) })).toBe(true);
    expect(enabled(c, 'setModulePatch', { moduleId: a.id, patch: p(1, 511, 16) })).toBe(true);
    expect(modules(run(c, 'setModulePatch', { moduleId: a.id, patch: null }))[0].dmx).toBeUndefined();
  });
  it('gives a CCT channel to tunable types only; a type change to one CCT drops it', () => {
    const three = withPreset('single', 1, 1);
    const c = run(run(three, 'removeModule', { moduleId: modules(three)[1].id }), 'removeModule', { moduleId: modules(three)[2].id });
    const m = modules(c)[0];
    expect(findModuleType(catalog, m.type).ccts.length).toBeGreaterThan(1);
    const patched = run(c, 'setModulePatch', { moduleId: m.id, patch: p(1, 1, 8, true) });
    const updown = run(patched, 'setModuleType', { moduleId: m.id, type: 'updown' });
    expect(modules(updown)[0].dmx).toEqual(p(1, 1, 8, false));
    expect(enabled(updown, 'setModulePatch', { moduleId: m.id, patch: p(1, 1, 8, true) })).toMatchObject({ ok: false, reason: expect.stringMatching(/one colour temperature only/) });
    // Auto-patch with CCT skips the channel for a type with one CCT.
    expect(modules(run(updown, 'autoPatch', { universe: 1, address: 1, resolution: 8, cct: true }))[0].dmx).toEqual(p(1, 1, 8, false));
  });
  it('removing a module, a rail or a system removes its patch entries; clearPatch removes all', () => {
    const c = run(twoSystems(), 'autoPatch', { universe: 1, address: 1, resolution: 8, cct: false });
    const first = modules(c)[0];
    const without = run(c, 'removeModule', { moduleId: first.id });
    expect(modules(without).some((m) => m.id === first.id)).toBe(false);
    expect(modules(without).filter((m) => m.dmx).length).toBe(8);
    // The freed channel can be taken by another module.
    expect(enabled(without, 'setModulePatch', { moduleId: modules(without)[0].id, patch: p(1, 1, 8) })).toBe(true);
    const noSystem = run(c, 'deleteSystem', { systemId: c.systems[0].id });
    expect(modules(noSystem).map((m) => m.dmx!.address)).toEqual([7, 8, 9]);
    expect(modules(run(c, 'clearPatch', {})).every((m) => m.dmx === undefined)).toBe(true);
  });
  it('patch edits are undoable store actions', () => {
    const store = createConfiguratorStore({ catalog, initial: twoSystems() });
    const before = store.getState().config;
    expect(store.getState().dispatch('autoPatch', { universe: 1, address: 1, resolution: 8, cct: true })).toEqual({ ok: true });
    const id = modules(store.getState().config)[1].id;
    expect(store.getState().dispatch('setModulePatch', { moduleId: id, patch: p(4, 100, 16, true) })).toEqual({ ok: true });
    expect(store.getState().dispatch('setModulePatch', { moduleId: id, patch: p(1, 1, 8) })).toMatchObject({ ok: false });
    expect(store.getState().undo()).toBe(true);
    expect(modules(store.getState().config)[1].dmx).toEqual(p(1, 3, 8, true)); // the first module took 1–2 (level, CCT)
    store.getState().undo();
    expect(store.getState().config).toBe(before);
    expect(checkAction(before, 'setModulePatch', { moduleId: id, patch: { universe: 1, address: 1, resolution: 12, cct: false } }, catalog)).toMatchObject({ ok: false, reason: expect.stringMatching(/^setModulePatch: patch\.resolution/) });
  });
});

describe('DMX patch: scene file version 2', () => {
  const patched = () => run(twoSystems(), 'autoPatch', { universe: 7, address: 100, resolution: 16, cct: true });
  it('is saved with the configuration, and round-trips through files and share links', () => {
    const c = patched();
    const file = JSON.parse(serializeConfiguration(c, catalog));
    expect(file.version).toBe(SCENE_FILE_VERSION);
    expect(file.configuration.systems[0].rails[0].modules[0].dmx).toEqual({ universe: 7, address: 100, resolution: 16, cct: true });
    expect(deserializeConfiguration(serializeConfiguration(c, catalog), catalog)).toEqual(c);
    expect(decodeShareString(encodeShareString(c, catalog), catalog)).toEqual(c);
  });
  it('migrates version 1 files: the fixture and a saved share string of version 1 still open', () => {
    const text = readFileSync('tests/fixtures/configurations/corner-l.luxbox.json', 'utf8');
    expect(JSON.parse(text).version).toBe(1);
    const c = deserializeConfiguration(text, catalog);
    expect(modules(c).length).toBe(6);
    expect(modules(c).every((m) => m.dmx === undefined)).toBe(true);
    // Saved again, it is a version 5 file with the same content, plus what version 4 added
    // (feeds.test.ts: each system hangs on suspensions and gets its planned feeds, ids from nextId).
    const again = JSON.parse(serializeConfiguration(c, catalog));
    expect(again.version).toBe(SCENE_FILE_VERSION);
    const old = JSON.parse(text).configuration;
    const feeds = again.configuration.systems.flatMap((s: { feeds: unknown[] }) => s.feeds).length;
    expect(again.configuration.systems.map(({ feeds: _f, mounting: _m, ...rest }: Record<string, unknown>) => rest)).toEqual(old.systems);
    expect(again.configuration.systems.every((s: { mounting: string }) => s.mounting === 'suspended')).toBe(true);
    expect(again.configuration.nextId).toBe(old.nextId + feeds);
    // A version 1 share link (base64url of the compact v1 JSON) decodes.
    const v1 = Buffer.from(JSON.stringify({ ...JSON.parse(text), version: 1 })).toString('base64url');
    expect(decodeShareString(v1, catalog)).toEqual(c);
  });
  it('refuses a patch in a version 1 file, and bad patches in version 2 files, naming the field', () => {
    const file = JSON.parse(serializeConfiguration(patched(), catalog));
    const read = (f: unknown) => () => deserializeConfiguration(JSON.stringify(f), catalog);
    expect(read({ ...file, version: 1 })).toThrow(SceneFileError);
    expect(read({ ...file, version: 1 })).toThrow('scene file: configuration.systems[0].rails[0].modules[0].dmx: needs "version": 2 (this file says version 1)');
    const bad = (edit: (m: Record<string, unknown>) => void) => {
      const f = JSON.parse(JSON.stringify(file));
      edit(f.configuration.systems[0].rails[0].modules[1].dmx);
      return f;
    };
    expect(read(bad((d) => (d.resolution = 12)))).toThrow(/modules\[1\]\.dmx\.resolution/);
    expect(read(bad((d) => (d.chanel = 1)))).toThrow(/unknown field 'chanel'/);
    expect(read(bad((d) => (d.address = 100)))).toThrow(/modules\[1\]\.dmx: DMX 7\/100–102 of module m\d+ overlaps module m\d+ \(7\/100–102\)/);
    expect(read(bad((d) => (d.address = 511)))).toThrow(/modules\[1\]\.dmx: channels 511–513 would run past 512/);
  });
});
