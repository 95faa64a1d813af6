/**
 * The bright-patch selection and its table without GL (selectBrightPatches.ts,
 * patchTable.ts): a uniform exitance takes nothing; one hot tile is taken,
 * as a rectangle with the tile's flux centred on its flux centroid.
 */
import { describe, expect, it } from 'vitest';
import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import { patchTable } from '../../../src/engines/bake/patchTable';
import { selectBrightPatches, type SurfaceTileSums } from '../../../src/engines/bake/selectBrightPatches';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { ATLAS_SOURCE, layoutTileFrame, type TileFrame } from '../../../src/engines/bake/tileFrame';

const layouts = surfaceLayouts({ width: 2, height: 2, depth: 2 }, 0.5, 512);
const floor = layouts[0];
const options = { maxPatches: 64, targetPeakedness: 1, minContrast: 3 };

/** Tile sums of the floor (4 × 4 texels of 0.5 m, one texel per tile) for direct lux e(i, j), ρ = 0.5 grey (or of another 2 × 2 m frame, its ρ). */
function floorSums(e: (i: number, j: number) => number, frame: TileFrame = layoutTileFrame(floor, [0.5, 0.5, 0.5])): SurfaceTileSums {
  const a = 0.25;
  const sums = new Float32Array(64);
  const moments = new Float32Array(64);
  for (let k = 0; k < 16; k++) {
    const lux = e(k % 4, Math.floor(k / 4));
    const y = frame.reflectance[0] * lux * a;
    sums.set([lux * a, lux * a, lux * a, (y * y) / a], 4 * k);
    // The texel centre is 0.25 m from the tile corner along u and v.
    moments.set([y * 0.25, y * 0.25, y * 0.0625, y * 0.0625], 4 * k);
  }
  return { frame, tile: 1, tilesU: 4, tilesV: 4, sums, moments };
}

describe('selectBrightPatches', () => {
  it('a uniform exitance has peakedness 1 and takes no tile', () => {
    const selection = selectBrightPatches([floorSums(() => 100)], options);
    expect(selection.patches).toHaveLength(0);
    expect(selection.peakedness).toBeCloseTo(1, 6);
  });

  it('one tile 1000× brighter than the rest is taken, with its reflected flux, centred on its texel', () => {
    const selection = selectBrightPatches([floorSums((i, j) => (i === 2 && j === 1 ? 1e5 : 100))], options);
    expect(selection.patches).toHaveLength(1);
    const [p] = selection.patches;
    expect([p.tileU, p.tileV, p.surface]).toEqual([2, 1, 0]);
    // ρ·E·A = 0.5 · 1e5 · 0.25 lm per channel.
    p.flux.forEach((f) => expect(f).toBeCloseTo(12500, 6));
    // Centre of texel (2, 1): x = 1.25, z = 0.75 on the floor (y = 0).
    expect(p.centre[0]).toBeCloseTo(1.25, 6);
    expect(p.centre[1]).toBe(0);
    expect(p.centre[2]).toBeCloseTo(0.75, 6);
    expect(selection.residualPeakedness).toBeLessThan(selection.peakedness);
  });

  it("on a chart of the atlas (a 40° slope, any axes) the patch lies in the chart's plane, with its half edges along the chart's axes, v turned to the front", () => {
    const c = Math.cos((40 * Math.PI) / 180);
    const sn = Math.sin((40 * Math.PI) / 180);
    // u along x, v up the slope; the front faces down into the room, so cross(u, v) (up and out) is the back: vSign −1.
    const slope: TileFrame = {
      index: ATLAS_SOURCE + 3,
      origin: [0.5, 1.2, 0.2],
      axisU: [1, 0, 0],
      axisV: [0, sn, -c],
      vSign: -1,
      lengthU: 2,
      lengthV: 2,
      width: 4,
      height: 4,
      area: 4,
      // A chart's sums carry each texel's ρ already: the selection multiplies by 1.
      reflectance: [1, 1, 1],
      chart: { id: 3, x: 10, y: 20 },
    };
    const selection = selectBrightPatches([floorSums((i, j) => (i === 1 && j === 2 ? 1e5 : 100), slope)], options);
    expect(selection.patches).toHaveLength(1);
    const [p] = selection.patches;
    expect(p.surface).toBe(ATLAS_SOURCE + 3);
    // Texel (1, 2)'s centre: u = 0.75, v = 1.25 from the origin along the chart's axes.
    const expected = [0.5 + 0.75, 1.2 + 1.25 * sn, 0.2 - 1.25 * c];
    p.centre.forEach((x, a) => expect(x).toBeCloseTo(expected[a], 9));
    expect(p.axisU).toEqual([1, 0, 0]);
    p.axisV.forEach((x, a) => expect(x).toBeCloseTo(-slope.axisV[a], 12));
    // Flux with ρ = 1 on the selection side: the sums themselves (1e5 · 0.25 lm).
    p.flux.forEach((f) => expect(f).toBeCloseTo(25000, 6));
    const row = patchTable([p]);
    expect(row[3]).toBe(ATLAS_SOURCE + 3);
    // Half edge v of the table: along −axisV, so cross(hu, hv) points to the front (down, into the room).
    const hv = [row[8], row[9], row[10]];
    expect(hv[1]).toBeLessThan(0);
  });
});

describe('patchTable', () => {
  it('packs centre + surface, the half edges as world vectors along the surface axes, and the exitance', () => {
    // West wall: u along z, v along y.
    const axes = { axisU: [0, 0, 1] as [number, number, number], axisV: [0, 1, 0] as [number, number, number] };
    const patch = { surface: 4, tileU: 0, tileV: 0, centre: [0, 1, 0.5] as [number, number, number], halfU: 0.1, halfV: 0.2, ...axes, flux: [1, 1, 1] as Rgb, exitance: [3, 4, 5] as Rgb };
    expect(Array.from(patchTable([patch]))).toEqual([0, 1, 0.5, 4, 0, 0, Math.fround(0.1), 0, 0, Math.fround(0.2), 0, 0, 3, 4, 5, 0]);
  });
});
