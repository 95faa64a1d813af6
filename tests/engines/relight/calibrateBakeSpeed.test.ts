import { describe, expect, it } from 'vitest';
import { luxOf } from '../../../src/engines/bake/bakedMaps';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { calibrateBakeSpeed, CALIBRATION_SCENE, CALIBRATION_SETTINGS, chooseQuality } from '../../../src/engines/relight/calibrateBakeSpeed';
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
      expect(c.renderer.length).toBeGreaterThan(0);
      expect(QUALITY_LEVEL_NAMES).toContain(chooseQuality(c));
    }
    // 3 × 2.5 × 3 m at 5 cm: floor and ceiling 60 × 60, four walls 60 × 50; one point source.
    const work = { texels: 2 * 60 * 60 + 4 * 60 * 50, pointSources: 1, samples: 32, bounces: 1 };
    expect(a.work).toEqual(work);
    expect(b.work).toEqual(work);
    expect(b.renderer).toBe(a.renderer);
  });

  it('bakes the documented scene: 100 cd isotropic, 1.25 m over the floor centre (E = I/h², CIE 171:2006 §5.2)', () => {
    const baker = createBaker(gl);
    try {
      const { maps } = baker.bake(CALIBRATION_SCENE, CALIBRATION_SETTINGS);
      const floor = maps.floor;
      const y = luxOf(floor.direct);
      const w = floor.layout.width;
      // The four texels around the centre: their centres are 2.5 cm off each axis, so cos θ / d² differs from 1/h² by 0.12 %.
      const centre = [w * 29 + 29, w * 29 + 30, w * 30 + 29, w * 30 + 30].map((i) => y[i]);
      const expected = 100 / 1.25 ** 2;
      for (const e of centre) expect(Math.abs(e / expected - 1)).toBeLessThan(0.005);
    } finally {
      baker.dispose();
    }
  });
});
