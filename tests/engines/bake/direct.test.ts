/**
 * Direct pass against the inverse-square cosine law at texel centres
 * (CIE 171:2006 §5.2): E = I(γ, C)·cosθ/d², the reference computed here in
 * float64 with the photometry module's own interpolation (intensity()) and
 * rotations written independently of the baker. And CIE 171 §5.4: in a black
 * room, Σ E·A over the six surfaces equals the source flux (with the default
 * texel means).
 */
import { describe, expect, it } from 'vitest';
import { SURFACE_NAMES, type Vec3 } from '../../../src/core/model/lightingScene/lightingScene';
import { intensity } from '../../../src/core/photometry/intensity';
import { integrateFlux } from '../../../src/core/photometry/flux';
import type { Photometry } from '../../../src/core/photometry/types';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { texelCentre } from '../../../src/engines/bake/surfaceLayout';
import { luxOf, type BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { anglesOf, isotropic, loadIes, totalFlux, uniformRoom, worldToLocal } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);
// Point sources only here: the law is for a point; openings are tested separately.
// Texel centres, not texel means (texelSupersampling 1): the law is checked point by point;
// the means are checked in stiff.test.ts.
const pointOnly = { sourceSpacing: 0, bounces: 0, texelSupersampling: 1 } as const;

interface Lamp {
  photometry: Photometry;
  position: Vec3;
  yaw: number;
  pitch: number;
  roll: number;
}

function referenceLux(lamp: Lamp, p: Vec3, normal: Vec3): number {
  const d: Vec3 = [p[0] - lamp.position[0], p[1] - lamp.position[1], p[2] - lamp.position[2]];
  const dist = Math.hypot(...d);
  const cos = -(d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]) / dist;
  if (cos <= 0) return 0;
  const [g, c] = anglesOf(worldToLocal(d, lamp.yaw, lamp.pitch, lamp.roll));
  return (intensity(lamp.photometry, g, c) * cos) / (dist * dist);
}

/** Largest relative error over texels whose reference exceeds `floor` × the maximum (away from zeros). */
function worstError(maps: BakedMaps, lamps: Lamp[], floor = 0.01): { worst: number; compared: number } {
  let worst = 0;
  let compared = 0;
  let max = 0;
  const refs = SURFACE_NAMES.map((name) => {
    const { layout, direct } = maps[name];
    const lux = luxOf(direct);
    const ref = new Float64Array(lux.length);
    for (let j = 0; j < layout.height; j++)
      for (let i = 0; i < layout.width; i++) {
        const p = texelCentre(layout, i, j);
        ref[j * layout.width + i] = lamps.reduce((s, l) => s + referenceLux(l, p, layout.normal), 0);
        max = Math.max(max, ref[j * layout.width + i]);
      }
    return { lux, ref };
  });
  for (const { lux, ref } of refs) {
    for (let k = 0; k < ref.length; k++) {
      if (ref[k] < floor * max) {
        // Below the floor only the absolute error is bounded.
        expect(Math.abs(lux[k] - ref[k])).toBeLessThanOrEqual(1e-3 * max);
        continue;
      }
      worst = Math.max(worst, Math.abs(lux[k] - ref[k]) / ref[k]);
      compared++;
    }
  }
  return { worst, compared };
}

describe('direct pass = I·cosθ/d² at texel centres', () => {
  it('isotropic point source in a 4 × 3 × 5 m room: ≤ 0.1 % everywhere', () => {
    const lamp: Lamp = { photometry: isotropic(1000), position: [1.3, 2.1, 3.7], yaw: 0, pitch: 0, roll: 0 };
    const { maps } = baker.bake({ room: uniformRoom(4, 3, 5, 0), luminaires: [lamp] }, { ...pointOnly, texelSize: 0.1 });
    const { worst, compared } = worstError(maps, [lamp], 0);
    console.info(`isotropic: worst relative error ${(100 * worst).toFixed(5)} %`);
    expect(compared).toBe(2 * (40 * 50 + 40 * 30 + 50 * 30));
    expect(worst).toBeLessThan(1e-3);
  });

  const realCases: [string, Partial<Lamp>][] = [
    ['bega_84693_narrow_spot.ies', { yaw: 0, pitch: 0, roll: 0 }],
    ['erco_kubus_floor_washlight.ies', { yaw: 35, pitch: 50, roll: 20 }],
    ['aec_italo_streetlight_full360.ies', { yaw: -70, pitch: 20, roll: 130 }],
    ['rab_halvs10_wall_sconce_199v.ies', { yaw: 90, pitch: 90, roll: 0 }],
    ['zumtobel_sloin_linear_isym4.ldt', { yaw: 10, pitch: 0, roll: 45 }],
    ['rab_pipxl70_flood_type_b_feet.ies', { yaw: 200, pitch: 30, roll: 0 }],
  ];
  for (const [file, angles] of realCases) {
    it(`${file}, yaw/pitch/roll ${angles.yaw}/${angles.pitch}/${angles.roll}: ≤ 1 % where E ≥ 1 % of the peak`, () => {
      const lamp: Lamp = { photometry: loadIes(file), position: [2.2, 2.4, 1.7], yaw: 0, pitch: 0, roll: 0, ...angles };
      const { maps } = baker.bake({ room: uniformRoom(4.5, 3, 3.5, 0), luminaires: [lamp] }, { ...pointOnly, texelSize: 0.05 });
      const { worst, compared } = worstError(maps, [lamp]);
      console.info(`${file}: worst relative error ${(100 * worst).toFixed(4)} % over ${compared} texels`);
      expect(compared).toBeGreaterThan(500);
      expect(worst).toBeLessThan(0.01);
    });
  }

  it('several luminaires sharing profiles add up', () => {
    const spotPh = loadIes('bega_84693_narrow_spot.ies');
    const wash = loadIes('erco_kubus_floor_washlight.ies');
    const lamps: Lamp[] = [
      { photometry: spotPh, position: [1, 2.9, 1], yaw: 0, pitch: 20, roll: 0 },
      { photometry: spotPh, position: [3, 2.9, 2], yaw: 90, pitch: 30, roll: 0 },
      { photometry: wash, position: [2, 0.3, 0.4], yaw: 180, pitch: 70, roll: 0 },
    ];
    const { maps, report } = baker.bake({ room: uniformRoom(4, 3, 3, 0), luminaires: lamps }, { ...pointOnly, texelSize: 0.05 });
    expect(worstError(maps, lamps).worst).toBeLessThan(0.01);
    // The tilted washlight on the floor reaches every surface.
    expect(report.directSkipped).toEqual([]);
  });

  it('skips surfaces no luminaire can reach (spot below the ceiling, pointing down)', () => {
    const lamp: Lamp = { photometry: loadIes('bega_84693_narrow_spot.ies'), position: [2, 2.9, 1.5], yaw: 0, pitch: 10, roll: 0 };
    const { maps, report } = baker.bake({ room: uniformRoom(4, 3, 3, 0), luminaires: [lamp] }, { ...pointOnly, texelSize: 0.1 });
    expect(report.directSkipped).toEqual(['ceiling']);
    expect(report.shaders.filter((s) => s.pass === 'direct').map((s) => s.surface)).not.toContain('ceiling');
    // The skip is exact: the reference is zero there too.
    expect(worstError(maps, [lamp]).worst).toBeLessThan(0.01);
  });
});

describe('CIE 171:2006 §5.4 flux conservation in a black room', () => {
  const cases: [string, Photometry, Partial<Lamp>][] = [
    ['isotropic 1000 cd', isotropic(1000), {}],
    ['bega_50975_downlight_lm1995_crlf.ies', loadIes('bega_50975_downlight_lm1995_crlf.ies'), {}],
    ['ledalite_pendant_direct_indirect_iesna95.ies (split opening)', loadIes('ledalite_pendant_direct_indirect_iesna95.ies'), { yaw: 30 }],
    ['erco_kubus_floor_washlight.ies tilted', loadIes('erco_kubus_floor_washlight.ies'), { pitch: 60, yaw: 20 }],
  ];
  for (const [name, photometry, angles] of cases) {
    it(`${name}: Σ E·A = Φ within 1 %`, () => {
      const phi = integrateFlux(photometry);
      const lamp = { photometry, position: [2, 2, 2] as Vec3, yaw: 0, pitch: 0, roll: 0, ...angles };
      const { maps, report } = baker.bake({ room: uniformRoom(4, 4, 4, 0), luminaires: [lamp] }, { texelSize: 0.05, bounces: 0 });
      expect(report.indirectEnabled).toBe(false);
      const flux = totalFlux(maps, 'direct');
      expect(Math.abs(flux - phi) / phi).toBeLessThan(0.01);
    });
  }
});
