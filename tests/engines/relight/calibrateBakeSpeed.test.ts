import { describe, expect, it } from 'vitest';
import { luxOf } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { calibrateBakeSpeed, CALIBRATION_PEAK_CD, CALIBRATION_SCENE, CALIBRATION_SETTINGS, chooseQuality } from '../../../src/engines/relight/calibrateBakeSpeed';
import { QUALITY_LEVEL_NAMES } from '../../../src/engines/relight/qualityLevels';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();

describe('calibrateBakeSpeed on headless-gl', () => {
  it('returns finite positive costs, the renderer, and the same fixed work on every call', () => {
    const a = calibrateBakeSpeed(gl);
    const b = calibrateBakeSpeed(gl);
    for (const c of [a, b]) {
      expect(Number.isFinite(c.msPerTexelSample) && c.msPerTexelSample > 0).toBe(true);
      expect(Number.isFinite(c.msPerTexelSource) && c.msPerTexelSource > 0).toBe(true);
      expect(Number.isFinite(c.compileMs) && c.compileMs >= 0).toBe(true);
      expect(Number.isFinite(c.directCompileMs) && c.directCompileMs >= 0).toBe(true);
      expect(Number.isFinite(c.msPerTexelBasis) && c.msPerTexelBasis > 0).toBe(true);
      expect(c.renderer.length).toBeGreaterThan(0);
      expect(QUALITY_LEVEL_NAMES).toContain(chooseQuality(c));
    }
    // 3 × 2.5 × 3 m at 5 cm: floor and ceiling 60 × 60, four walls 60 × 50; a 5 × 2 grid of point sources.
    const work = { texels: 2 * 60 * 60 + 4 * 60 * 50, pointSources: 10, samples: 32, bounces: 1 };
    expect(a.work).toEqual(work);
    expect(b.work).toEqual(work);
    expect(b.renderer).toBe(a.renderer);
  });

  it('bakes the documented scene: 10 point sources of a cosine distribution 1.25 m over the floor centre (E = Σ I·cos γ·cos θ/d², CIE 171:2006 §5.2)', () => {
    const baker = createBaker(gl);
    try {
      const { maps, report } = baker.bake(CALIBRATION_SCENE, CALIBRATION_SETTINGS);
      expect(report.pointSources).toBe(10);
      const floor = maps.floor;
      const y = luxOf(floor.direct);
      const w = floor.layout.width;
      // The opening's 5 × 2 cells (0.24 × 0.09 m at 5 cm spacing), each 1/10 of the intensity, 1.25 m up.
      const sources = [-0.096, -0.048, 0, 0.048, 0.096].flatMap((x) => [-0.0225, 0.0225].map((z) => [1.5 + x, 1.5 + z]));
      const h = 1.25;
      // Straight below a facing-down source cos γ = cos θ = h/d: each adds (I/10)·h²/d⁴. The table's 5° linear
      // interpolation of cos γ is off by < 0.03 % within the 5° these points see; the texel mean differs from its centre by less.
      const exact = (px: number, pz: number) => sources.reduce((e, [sx, sz]) => e + ((CALIBRATION_PEAK_CD / 10) * h * h) / (h * h + (px - sx) ** 2 + (pz - sz) ** 2) ** 2, 0);
      // The four texels around the centre (5 cm texels, centres 2.5 cm off each axis); the floor's u, v run along x, z.
      for (const [i, j] of [
        [29, 29],
        [30, 29],
        [29, 30],
        [30, 30],
      ]) {
        const e = y[j * w + i];
        const ref = exact(0.05 * (i + 0.5), 0.05 * (j + 0.5));
        expect(Math.abs(e / ref - 1)).toBeLessThan(0.005);
      }
    } finally {
      baker.dispose();
    }
  });
});
