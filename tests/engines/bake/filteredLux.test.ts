import { describe, expect, it } from 'vitest';
import { moduleLightColour } from '../../../src/core/model/modules/moduleFilter';
import { toLightingScene } from '../../../src/core/model/files/toLightingScene';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import { resolveBakeSettings } from '../../../src/engines/bake/bakeSettings';
import { directAtPoint } from '../../../src/engines/bake/directAtPoint';
import { resolveBakeSceneSync } from '../../../src/engines/bake/resolveBakeScene';
import { scenePointSources } from '../../../src/engines/bake/scenePointSources';
import { groupLuminaires, groupWeight } from '../../../src/engines/relight/luminaireGroups';
import { createNodePhotometryLoader } from '../../../src/hosts/node/createNodePhotometryLoader';
import { catalog, only, run, withPreset } from '../../core/model/helpers';

const lux = (rgb: readonly number[]) => rgb.reduce((a, v, i) => a + v * LUMINANCE_WEIGHTS[i], 0);

describe('a colour filter in the light that reaches the floor', () => {
  it('floor lux under three filtered spots = τ_v × the unfiltered lux at every point (0.6 ND and a CTB)', () => {
    const plain = withPreset('single', 1, 1);
    const ids = only(plain).rails[0].modules.map((m) => m.id);
    const load = createNodePhotometryLoader();
    const floorLux = (s: typeof plain) => {
      const scene = resolveBakeSceneSync(toLightingScene(s, catalog, { photometryBase: 'public/' }), load);
      const lamps = scenePointSources(scene, resolveBakeSettings({}));
      return [0.5, 1, 1.5, 2, 2.5].map((x) => lux(directAtPoint(lamps, [x, 0, 1.2], [0, 1, 0])));
    };
    const ref = floorLux(plain);
    expect(Math.min(...ref)).toBeGreaterThan(1);
    for (const filter of ['lee-210', 'lee-201']) {
      const s = ids.reduce((c, moduleId) => run(c, 'setModuleFilter', { moduleId, filter }), plain);
      const tau = moduleLightColour({ cct: 3000, filter }).transmission;
      floorLux(s).forEach((e, i) => expect(e / ref[i]).toBeCloseTo(tau, 9));
    }
  });

  it('changing a filter is a relight: the same luminaire groups (bases), only the weights change, by τ_v in luminance', () => {
    const plain = withPreset('single', 1, 1);
    const [m] = only(plain).rails[0].modules.map((x) => x.id);
    const gel = run(plain, 'setModuleFilter', { moduleId: m, filter: 'lee-201' });
    const load = createNodePhotometryLoader();
    const lum = (s: typeof plain) => resolveBakeSceneSync(toLightingScene(s, catalog, { photometryBase: 'public/' }), load).luminaires;
    const [a, b] = [lum(plain), lum(gel)];
    const [ga, gb] = [groupLuminaires(a), groupLuminaires(b)];
    expect(gb.map((g) => g.key)).toEqual(ga.map((g) => g.key));
    const tau = moduleLightColour({ cct: 3000, filter: 'lee-201' }).transmission;
    const g0 = ga.findIndex((g) => g.members.includes(0));
    expect(lux(groupWeight(gb[g0], b)) / lux(groupWeight(ga[g0], a))).toBeCloseTo(tau, 12);
  });
});
