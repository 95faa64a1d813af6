/**
 * Dense profile tables (docs/baker.md, "Profile table") change the maps only
 * within 1e-4 of their peak: the same scenes baked with the file's own grid
 * and bin tables (`profileLookup: 'measured'`, the lookup before dense tables)
 * and with the dense grids (the default), compared map by map. Scenes: every
 * real photometry file in public/ies (turned, tilted, near and far walls),
 * the stiff narrow spot 15 cm from a wall with texel means, and the CIE 171
 * style isotropic source. Direct maps are deterministic; total maps follow
 * with the same seed (the bright-patch selection and the gather read the
 * direct maps, so they move by as little).
 */
import { readdirSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import type { BakedMaps } from '../../../src/engines/bake/bakedMaps';
import type { BakeSettings } from '../../../src/engines/bake/bakeSettings';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { isotropic, loadIes, spot, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);

/** Largest |dense − measured| over the largest |measured|, per surface and kind. */
function mapDifference(measured: BakedMaps, dense: BakedMaps, kind: 'direct' | 'total'): number {
  let worst = 0;
  for (const name of SURFACE_NAMES) {
    const a = measured[name][kind];
    const b = dense[name][kind];
    let peak = 0;
    let diff = 0;
    for (let i = 0; i < a.length; i++) {
      peak = Math.max(peak, Math.abs(a[i]));
      diff = Math.max(diff, Math.abs(a[i] - b[i]));
    }
    if (peak > 0) worst = Math.max(worst, diff / peak);
  }
  return worst;
}

function bothLookups(scene: BakeScene, settings: Partial<BakeSettings>) {
  const measured = baker.bake(scene, { ...settings, profileLookup: 'measured' }).maps;
  const dense = baker.bake(scene, { ...settings, profileLookup: 'dense' }).maps;
  const d = { direct: mapDifference(measured, dense, 'direct'), total: mapDifference(measured, dense, 'total') };
  console.log(`dense vs measured: direct ${d.direct.toExponential(2)}, total ${d.total.toExponential(2)} of the peak`);
  return d;
}

const files = readdirSync('public/ies').filter((f) => /\.ies$/i.test(f));

describe('dense profile tables: the same maps within 1e-4 of the peak', () => {
  for (let group = 0; group < files.length; group += 6) {
    const names = files.slice(group, group + 6);
    it(`real photometry: ${names.join(', ')}`, () => {
      const scene: BakeScene = {
        room: uniformRoom(4, 2.8, 3, 0.5),
        luminaires: names.map((name, k) => ({ photometry: loadIes(name), position: [0.6 + 0.6 * k, 1.2 + 0.25 * k, 0.4 + 0.4 * k] as [number, number, number], yaw: 37 * k, pitch: 25 * (k % 3), roll: 11 * k })),
      };
      const d = bothLookups(scene, { texelSize: 0.1, samples: 32, bounces: 2, maxTextureSize: 64 });
      expect(d.direct).toBeLessThanOrEqual(1e-4);
      expect(d.total).toBeLessThanOrEqual(1e-4);
    });
  }

  it('stiff: a narrow spot 15 cm from a wall, texel means', () => {
    const scene: BakeScene = { room: uniformRoom(2.5, 2.4, 2, 0.7), luminaires: [{ photometry: spot(20000, 6, 2, 0.5), position: [1.25, 1.2, 0.15], yaw: 0, pitch: -90, roll: 0 }] };
    const d = bothLookups(scene, { texelSize: 0.05, samples: 32, bounces: 2 });
    expect(d.direct).toBeLessThanOrEqual(1e-4);
    expect(d.total).toBeLessThanOrEqual(1e-4);
  });

  it('CIE 171 style: an isotropic source in a grey box', () => {
    const scene: BakeScene = { room: uniformRoom(3, 3, 3, 0.5), luminaires: [{ photometry: isotropic(1000), position: [1.5, 1.5, 1.5], yaw: 0, pitch: 0, roll: 0 }] };
    const d = bothLookups(scene, { texelSize: 0.1, samples: 32, bounces: 2 });
    expect(d.direct).toBeLessThanOrEqual(1e-4);
    expect(d.total).toBeLessThanOrEqual(1e-4);
  });
});
