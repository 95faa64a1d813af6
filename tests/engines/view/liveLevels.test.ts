import { describe, expect, it } from 'vitest';
import { defaultCatalog as catalog } from '../../../src/core/catalog/defaultCatalog';
import { bindAction } from '../../../src/core/model/actions/actionDefinitions';
import { createConfiguration, type Configuration } from '../../../src/core/model/configuration/configuration';
import { modulesInOrder } from '../../../src/core/model/modules/dmxPatch';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import { cctToLinearRgb } from '../../../src/core/photometry/cct';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { groupLuminaires } from '../../../src/engines/relight/luminaireGroups';
import { applyLiveLevels } from '../../../src/engines/view/applyLiveLevels';
import { levelsFromFrames, sameLevels } from '../../../src/engines/view/liveLevels';

const run = (s: Configuration, name: string, params: unknown): Configuration => {
  const r = bindAction(name, params, catalog).attempt(s);
  if (!r.ok) throw new Error(r.reason);
  return r.next;
};

/** corner-l (4 spots/floods, 2 washers: all tunable), auto-patched 16-bit with CCT from 1/1: three channels each. */
function patched(): Configuration {
  const c = run(createConfiguration({ width: 8, depth: 6, height: 3 }), 'placePreset', { presetId: 'corner-l', x: 1, z: 4 });
  return run(c, 'autoPatch', { universe: 1, address: 1, resolution: 16, cct: true });
}

describe('levels from frames', () => {
  it('decodes each patched module from the latest frame of its universe', () => {
    const c = patched();
    const ids = modulesInOrder(c).map((m) => m.module.id);
    const ch = new Array(512).fill(0);
    ch.splice(0, 3, 255, 255, 0); // module 1: full, 2700 K
    ch.splice(3, 3, 128, 0, 255); // module 2: 128·256/65535, 4000 K
    ch.splice(6, 3, 0, 1, 51); // module 3: the fine byte alone, 2960 K
    const levels = levelsFromFrames(c, catalog, new Map([[1, ch]]));
    expect(levels.size).toBe(6);
    expect(levels.get(ids[0])).toEqual({ dimming: 1, cct: 2700 });
    expect(levels.get(ids[1])).toEqual({ dimming: (128 * 256) / 65535, cct: 4000 });
    expect(levels.get(ids[2])!.dimming).toBeCloseTo(1 / 65535, 12);
    expect(levels.get(ids[2])!.cct).toBeCloseTo(2960, 9);
    expect(levels.get(ids[5])).toEqual({ dimming: 0, cct: 2700 });
  });
  it('leaves out modules that are not patched or whose universe has sent nothing', () => {
    let c = patched();
    const ids = modulesInOrder(c).map((m) => m.module.id);
    c = run(c, 'setModulePatch', { moduleId: ids[0], patch: null });
    c = run(c, 'setModulePatch', { moduleId: ids[1], patch: { universe: 2, address: 1, resolution: 8, cct: false } });
    const levels = levelsFromFrames(c, catalog, new Map([[1, new Array(512).fill(255)]]));
    expect(levels.has(ids[0])).toBe(false);
    expect(levels.has(ids[1])).toBe(false);
    expect(levels.get(ids[2])).toEqual({ dimming: 1, cct: 4000 });
    const both = levelsFromFrames(
      c,
      catalog,
      new Map([
        [1, new Array(512).fill(255)],
        [2, [102]],
      ]),
    );
    expect(both.get(ids[1])).toEqual({ dimming: 0.4, cct: null }); // 8-bit, no CCT channel: the module's own colour
    expect(levelsFromFrames(c, catalog, new Map())).toEqual(new Map());
  });
  it('tells repeated frames from changed ones', () => {
    const c = patched();
    const a = levelsFromFrames(c, catalog, new Map([[1, new Array(512).fill(7)]]));
    expect(sameLevels(a, levelsFromFrames(c, catalog, new Map([[1, new Array(512).fill(7)]])))).toBe(true);
    expect(sameLevels(a, levelsFromFrames(c, catalog, new Map([[1, new Array(512).fill(8)]])))).toBe(false);
    expect(sameLevels(null, a)).toBe(false);
  });
});

describe('the live overlay on a bake scene', () => {
  it('replaces dimming and colour only, so every relight group keeps its key (no bake)', () => {
    const c = patched();
    const scene = toLightingScene(c, catalog);
    const photometry = { id: 'shared' } as unknown as BakeScene['luminaires'][number]['photometry'];
    const bake: BakeScene = { room: scene.room, luminaires: scene.luminaires.map(({ id: _id, photometry: _p, ...l }) => ({ ...l, photometry })) };
    const ids = scene.luminaires.map((l) => l.id!);
    const levels = new Map([
      [ids[0], { dimming: 0.25, cct: 3500 }],
      [ids[2], { dimming: 0, cct: null }],
    ]);
    const lit = applyLiveLevels(bake, ids, levels);
    expect(lit.luminaires[0].dimming).toBe(0.25);
    expect(lit.luminaires[0].color).toEqual(cctToLinearRgb(3500));
    expect(lit.luminaires[2].dimming).toBe(0);
    expect(lit.luminaires[2].color).toEqual(bake.luminaires[2].color);
    expect(lit.luminaires[1]).toBe(bake.luminaires[1]);
    expect(groupLuminaires(lit.luminaires).map((g) => g.key)).toEqual(groupLuminaires(bake.luminaires).map((g) => g.key));
    // The input scene (the configuration's look) is untouched, and no levels: the same scene.
    expect(bake.luminaires[0].dimming).toBe(1);
    expect(applyLiveLevels(bake, ids, new Map())).toBe(bake);
  });
});
