import { describe, expect, it } from 'vitest';
import { defaultSurfaceFinishes } from '../../../../src/core/catalog/surfaceFinishes';
import { DEFAULT_REFLECTANCE, createConfiguration } from '../../../../src/core/model/configuration/configuration';
import { SURFACE_NAMES } from '../../../../src/core/model/lightingScene/lightingScene';
import { MAX_REFLECTANCE, luminousReflectance, reflectanceRgb } from '../../../../src/core/model/lightingScene/reflectance';
import { deserializeConfiguration, serializeConfiguration } from '../../../../src/core/model/files/sceneFile';
import { SceneFileError } from '../../../../src/core/model/files/sceneFileError';
import { decodeShareString, encodeShareString } from '../../../../src/core/model/files/shareLink';
import { SurfaceFinishError, finishesFor, matchFinish, parseSurfaceFinishes } from '../../../../src/core/model/catalogSchema/surfaceFinish';
import { toLightingScene } from '../../../../src/core/model/files/toLightingScene';
import { validate } from '../../../../src/core/model/validation/validate';
import { createConfiguratorStore } from '../../../../src/core/store/createConfiguratorStore';
import { bindAction } from '../../../../src/core/model/actions/actionDefinitions';
import { catalog, enabled, run, withPreset } from '../helpers';

const WALLS = ['north', 'south', 'west', 'east'] as const;

describe('setReflectance', () => {
  it('sets one surface, or all four walls at once, and the lighting scene carries it', () => {
    const a = run(withPreset('single', 1, 1), 'setReflectance', { surface: 'floor', value: [0.089, 0.101, 0.12] });
    expect(a.room.reflectance.floor).toEqual([0.089, 0.101, 0.12]);
    const b = run(a, 'setReflectance', { surface: 'walls', value: 0.7 });
    for (const w of WALLS) expect(b.room.reflectance[w]).toBe(0.7);
    const c = run(b, 'setReflectance', { surface: 'east', value: [0.6, 0.5, 0.4] });
    expect(c.room.reflectance).toEqual({ floor: [0.089, 0.101, 0.12], ceiling: 0.8, north: 0.7, south: 0.7, west: 0.7, east: [0.6, 0.5, 0.4] });
    // geometry untouched: same systems object, same luminaires
    expect(c.systems).toBe(a.systems);
    const scene = toLightingScene(c, catalog);
    expect(scene.room.reflectance).toEqual(c.room.reflectance);
    expect(validate(c, catalog)).toEqual([]);
  });

  it('accepts the cap itself and zero, refuses beyond them with a reason; performing anyway breaks validate()', () => {
    const s = createConfiguration();
    expect(enabled(s, 'setReflectance', { surface: 'ceiling', value: MAX_REFLECTANCE })).toBe(true);
    expect(enabled(s, 'setReflectance', { surface: 'floor', value: 0 })).toBe(true);
    for (const [surface, value] of [
      ['ceiling', 0.96],
      ['floor', -0.01],
      ['walls', [0.5, 1.2, 0.5]],
    ] as const) {
      const e = enabled(s, 'setReflectance', { surface, value });
      expect(e).not.toBe(true);
      if (e !== true) expect(e.reason).toMatch(new RegExp(`^${surface}: reflectance .* is outside \\[0, 0\\.95\\]`));
      const broken = bindAction('setReflectance', { surface, value }, catalog).perform(s);
      const problems = validate(broken, catalog);
      expect(problems.map((p) => p.code)).toContain('reflectance');
      expect(problems[0].path).toBe(`room.reflectance.${surface === 'walls' ? 'north' : surface}`);
    }
  });

  it('bad parameters name the field', () => {
    expect(() => bindAction('setReflectance', { surface: 'roof', value: 0.5 }, catalog)).toThrow(/setReflectance: surface: /);
    expect(() => bindAction('setReflectance', { surface: 'floor', value: [0.5, 0.5] }, catalog)).toThrow(/setReflectance: value/);
    expect(() => bindAction('setReflectance', { surface: 'floor', value: Number.NaN }, catalog)).toThrow(/setReflectance: value/);
  });

  it('validate() catches reflectances outside the cap, wrong shapes and missing surfaces', () => {
    const s = createConfiguration();
    const bad = { ...s, room: { ...s.room, reflectance: { ...s.room.reflectance, west: [0.5, 0.5] as unknown as number, floor: Number.POSITIVE_INFINITY } } };
    expect(validate(bad, catalog).map((p) => p.path)).toEqual(['room.reflectance.floor', 'room.reflectance.west']);
  });

  it('is undoable through the store like every action', () => {
    const store = createConfiguratorStore({ catalog });
    expect(store.getState().dispatch('setReflectance', { surface: 'walls', value: [0.402, 0.476, 0.335] })).toEqual({ ok: true });
    expect(store.getState().config.room.reflectance.south).toEqual([0.402, 0.476, 0.335]);
    const refused = store.getState().dispatch('setReflectance', { surface: 'floor', value: 0.99 });
    expect(refused.ok).toBe(false);
    expect(store.getState().undo()).toBe(true);
    expect(store.getState().config.room.reflectance).toEqual(DEFAULT_REFLECTANCE);
    expect(store.getState().redo()).toBe(true);
    expect(store.getState().config.room.reflectance.north).toEqual([0.402, 0.476, 0.335]);
  });
});

describe('scene file reflectances', () => {
  const finished = () => run(run(withPreset('single', 1, 1), 'setReflectance', { surface: 'floor', value: [0.226, 0.097, 0.038] }), 'setReflectance', { surface: 'west', value: 0.6 });

  it('round-trip through the file and the share link', () => {
    const s = finished();
    expect(deserializeConfiguration(serializeConfiguration(s, catalog), catalog)).toEqual(s);
    expect(decodeShareString(encodeShareString(s, catalog), catalog)).toEqual(s);
  });

  it('older files: values above the 0.95 cap are lowered to it, left-out surfaces get the defaults', () => {
    const f = JSON.parse(serializeConfiguration(finished(), catalog));
    f.configuration.room.reflectance = { floor: 0.97, ceiling: [0.99, 0.9, 0.96], north: 0.3 };
    const c = deserializeConfiguration(JSON.stringify(f), catalog);
    expect(c.room.reflectance).toEqual({ floor: 0.95, ceiling: [0.95, 0.9, 0.95], north: 0.3, south: 0.5, west: 0.5, east: 0.5 });
    delete f.configuration.room.reflectance;
    expect(deserializeConfiguration(JSON.stringify(f), catalog).room.reflectance).toEqual(DEFAULT_REFLECTANCE);
    expect(validate(c, catalog)).toEqual([]);
  });

  it('refuses reflectances at or above 1 and below 0, naming the field', () => {
    const f = JSON.parse(serializeConfiguration(finished(), catalog));
    f.configuration.room.reflectance.east = 1;
    expect(() => deserializeConfiguration(JSON.stringify(f), catalog)).toThrow(SceneFileError);
    expect(() => deserializeConfiguration(JSON.stringify(f), catalog)).toThrow(/configuration\.room\.reflectance\.east: /);
    f.configuration.room.reflectance.east = [0.5, -0.1, 0.5];
    expect(() => deserializeConfiguration(JSON.stringify(f), catalog)).toThrow(/configuration\.room\.reflectance\.east/);
  });
});

/** sRGB transfer function, IEC 61966-2-1:1999 §5.2 (independent of the app, which stores both forms as data). */
function srgbByte(linear: number): number {
  const v = linear <= 0.0031308 ? 12.92 * linear : 1.055 * linear ** (1 / 2.4) - 0.055;
  return Math.round(v * 255);
}

describe('surface finishes', () => {
  it('each display colour is the sRGB encoding of its linear reflectance (±1/255 per channel)', () => {
    for (const f of defaultSurfaceFinishes) {
      const rgb = reflectanceRgb(f.reflectance);
      const hex = [1, 3, 5].map((i) => parseInt(f.display.slice(i, i + 2), 16));
      rgb.forEach((v, i) => expect(Math.abs(srgbByte(v) - hex[i]), `${f.id} channel ${i}`).toBeLessThanOrEqual(1));
      rgb.forEach((v) => expect(v).toBeLessThanOrEqual(MAX_REFLECTANCE));
    }
  });

  it('luminous reflectances lie in the ranges their sources state (EN 12464-1:2021 §4.2.3 for floors)', () => {
    const y = (id: string) => luminousReflectance(defaultSurfaceFinishes.find((f) => f.id === id)!.reflectance);
    expect(y('white-paint')).toBeCloseTo(0.8, 3);
    expect(y('warm-white')).toBeCloseTo(0.7, 2);
    expect(y('sage-green')).toBeCloseTo(0.45, 2);
    expect(y('light-oak')).toBeCloseTo(0.35, 2);
    expect(y('concrete')).toBeCloseTo(0.3, 2);
    expect(y('dark-walnut')).toBeCloseTo(0.12, 2);
    expect(y('dark-slate')).toBeCloseTo(0.1, 2);
    // Every floor finish a shop would call "normal" stays within 0.1..0.6; ceilings are bright.
    for (const f of finishesFor(defaultSurfaceFinishes, 'floor')) expect(luminousReflectance(f.reflectance)).toBeLessThanOrEqual(0.6);
    for (const f of finishesFor(defaultSurfaceFinishes, 'ceiling')) expect(luminousReflectance(f.reflectance)).toBeGreaterThanOrEqual(0.3);
  });

  it('the default room is made of listed finishes, and every finish is accepted by setReflectance', () => {
    for (const s of SURFACE_NAMES) expect(matchFinish(defaultSurfaceFinishes, DEFAULT_REFLECTANCE[s]), s).not.toBeNull();
    expect(matchFinish(defaultSurfaceFinishes, 0.42)).toBeNull();
    expect(matchFinish(defaultSurfaceFinishes, [0.5, 0.5, 0.5])?.id).toBe('mid-grey');
    const s = createConfiguration();
    for (const f of defaultSurfaceFinishes) expect(enabled(s, 'setReflectance', { surface: 'floor', value: f.reflectance })).toBe(true);
  });

  it('a broken finish list fails loudly, naming the field', () => {
    const good = { formatVersion: 1, finishes: defaultSurfaceFinishes.map((f) => ({ ...f })) };
    const bad = (mutate: (d: typeof good) => void, msg: RegExp) => {
      const d = structuredClone(good);
      mutate(d);
      expect(() => parseSurfaceFinishes(d, 'my.json')).toThrow(SurfaceFinishError);
      expect(() => parseSurfaceFinishes(d, 'my.json')).toThrow(msg);
    };
    bad((d) => (d.finishes[0].reflectance = 0.97), /^my\.json: finishes\[0\]\.reflectance: reflectance 0\.97 is outside/);
    bad((d) => (d.finishes[1].id = d.finishes[0].id), /finishes\[1\]\.id: duplicate finish id 'white-paint'/);
    bad((d) => (d.finishes[2].display = 'grey'), /finishes\[2\]\.display: must be an sRGB colour/);
    bad((d) => (d.finishes = d.finishes.filter((f) => !f.uses.includes('floor'))), /no finish is offered for the floor/);
  });
});
