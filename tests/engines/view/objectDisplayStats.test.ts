/**
 * What the view derives from the objects' light: auto exposure and the lux scale top count the
 * objects by their covered area (analytic log averages and percentiles), objectStats reads a
 * table's top, its mean and the floor under it, and the reflectance dilation fills the gutters.
 */
import { describe, expect, it } from 'vitest';
import { furnitureMesh } from '../../../src/core/model/objects/furniture/furnitureLibrary';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../../src/core/model/lightingScene/lightingScene';
import { prepareObjects } from '../../../src/engines/bake/objects/prepareObjects';
import { surfaceLayouts, texelArea, texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { emptyLitMaps } from '../../../src/engines/relight/relightMaps';
import { AUTO_EXPOSURE_KEY, autoExposure } from '../../../src/engines/view/autoExposure';
import { dilateReflectance } from '../../../src/engines/view/dilateReflectance';
import { luxScaleTop } from '../../../src/engines/view/luxScaleTop';
import { objectStats } from '../../../src/engines/view/objectStats';

const room = { width: 5, height: 2.8, depth: 4 };
const lit = emptyLitMaps(surfaceLayouts(room, 0.1, 256));
const grey = (r: number) => Object.fromEntries(SURFACE_NAMES.map((n) => [n, [r, r, r]])) as Record<SurfaceName, Rgb>;
const prepared = prepareObjects([{ id: 'table', mesh: furnitureMesh('dining-table'), position: [2.5, 0, 2], yaw: 0, scale: 1 }], { texelSize: 0.1 });
const { atlas } = prepared;
const texels = atlas.width * atlas.height;

/** Every atlas texel at `lux` (white), the top's texels at `topLux`. */
function objectLight(lux: number, topLux = lux): Float32Array {
  const total = new Float32Array(texels * 3);
  for (let t = 0; t < texels; t++) {
    const top = atlas.normal[4 * t + 1] > 0.99 && atlas.position[4 * t + 1] > 0.74;
    total.fill(top ? topLux : lux, 3 * t, 3 * t + 3);
  }
  return total;
}

describe('objects in auto exposure and the lux scale', () => {
  for (const name of SURFACE_NAMES) lit.maps[name].total.fill(100);
  const wallArea = SURFACE_NAMES.reduce((a, n) => a + texelArea(lit.layouts[n]) * lit.layouts[n].width * lit.layouts[n].height, 0);
  let objectArea = 0;
  for (let t = 0; t < texels; t++) objectArea += atlas.position[4 * t + 3] * atlas.texelSize ** 2;

  it('auto exposure: the area-weighted log average of walls (ρ 0.5, 100 lx) and the table (its own ρ per texel, 400 lx)', () => {
    // The table's finishes differ per part: its log luminance is the coverage-weighted mean of log(ρ_Y · 400 / π).
    let logObject = 0;
    for (let t = 0; t < texels; t++) {
      const a = atlas.position[4 * t + 3] * atlas.texelSize ** 2;
      if (a <= 0) continue;
      const rhoY = 0.2126 * atlas.reflectance[4 * t] + 0.7152 * atlas.reflectance[4 * t + 1] + 0.0722 * atlas.reflectance[4 * t + 2];
      logObject += a * Math.log((rhoY * 400) / Math.PI);
    }
    const expected = AUTO_EXPOSURE_KEY / Math.exp((wallArea * Math.log((0.5 * 100) / Math.PI) + logObject) / (wallArea + objectArea));
    const got = autoExposure(lit, grey(0.5), { atlas, total: objectLight(400) });
    expect(got / expected).toBeCloseTo(1, 6);
    expect(autoExposure(lit, grey(0.5))).toBeCloseTo(AUTO_EXPOSURE_KEY / ((0.5 * 100) / Math.PI), 9);
    // Area matters: the table's ~7 m² against the room's 75 m² moves the exposure by less than its log share.
    expect(objectArea).toBeGreaterThan(4);
    expect(objectArea).toBeLessThan(12);
  });

  it('the scale top counts the table by area: 5000 lx on more than 1 % of the area moves the 99th percentile there', () => {
    expect(luxScaleTop(lit)).toBeGreaterThan(100);
    expect(luxScaleTop(lit)).toBeLessThan(100 * 10 ** (1 / 16) * 1.001);
    expect(objectArea / (wallArea + objectArea)).toBeGreaterThan(0.01);
    const top = luxScaleTop(lit, 0.99, { atlas, total: objectLight(5000) });
    expect(top).toBeGreaterThan(5000);
    expect(top).toBeLessThan(5000 * 10 ** (1 / 16) * 1.001);
  });
});

describe('objectStats', () => {
  it('top = the up-facing texels at the top height, avg = coverage-weighted mean, floor under = the floor map under the plan bounds', () => {
    const floor = lit.layouts.floor;
    const floorMap = lit.maps.floor.total;
    const b = prepared.objects[0].bounds;
    let under = 0;
    for (let j = 0; j < floor.height; j++) {
      for (let i = 0; i < floor.width; i++) {
        const p = texelCentre(floor, i, j);
        const inside = p[0] >= b.min[0] && p[0] <= b.max[0] && p[2] >= b.min[2] && p[2] <= b.max[2];
        if (inside) under++;
        floorMap.fill(inside ? 20 : 80, 3 * (j * floor.width + i), 3 * (j * floor.width + i) + 3);
      }
    }
    // 1.8 × 0.9 m under 0.1 m texels: 18 × 9 centres, or a row more where a bound falls on a row of centres.
    expect(under).toBeGreaterThanOrEqual(162);
    expect(under).toBeLessThanOrEqual(190);
    const [s] = objectStats(lit, prepared, { atlas, total: objectLight(100, 700) });
    expect(s.id).toBe('table');
    expect(s.top).toBeCloseTo(700, 3);
    expect(s.floorUnder).toBeCloseTo(20, 4);
    // The top (1.8 × 0.9 m) is a known share of the table's area.
    let area = 0;
    for (let t = 0; t < texels; t++) area += atlas.position[4 * t + 3] * atlas.texelSize ** 2;
    const topShare = (1.8 * 0.9) / area;
    expect(s.avg).toBeCloseTo(100 + 600 * topShare, 0);
  });
});

describe('dilateReflectance', () => {
  it("fills every empty texel next to a chart with a covered neighbour's ρ and object index, keeps covered texels", () => {
    const out = dilateReflectance(atlas);
    let filledNext = 0;
    for (let j = 0; j < atlas.height; j++) {
      for (let i = 0; i < atlas.width; i++) {
        const t = j * atlas.width + i;
        if (atlas.position[4 * t + 3] > 0) {
          expect(Array.from(out.subarray(4 * t, 4 * t + 4))).toEqual(Array.from(atlas.reflectance.subarray(4 * t, 4 * t + 4)));
          continue;
        }
        const nextToChart = [
          [-1, 0],
          [1, 0],
          [0, -1],
          [0, 1],
        ].some(([di, dj]) => {
          const x = i + di;
          const y = j + dj;
          return x >= 0 && y >= 0 && x < atlas.width && y < atlas.height && atlas.position[4 * (y * atlas.width + x) + 3] > 0;
        });
        if (nextToChart) {
          expect(out[4 * t + 3]).toBe(1);
          expect(out[4 * t] + out[4 * t + 1] + out[4 * t + 2]).toBeGreaterThan(0);
          filledNext++;
        }
      }
    }
    expect(filledNext).toBeGreaterThan(0);
  });
});
