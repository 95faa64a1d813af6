/**
 * Extreme scenes: none may produce NaN, Inf or negative lux; the physics
 * must still hold where it can be checked (flux in a black room).
 */
import { describe, expect, it } from 'vitest';
import { createBaker } from '../../../src/engines/bake/createBaker';
import { integrateFlux } from '../../../src/core/photometry/flux';
import { parseLightingScene } from '../../../src/core/model/lightingScene/parseLightingScene';
import { InputError } from '../../../src/core/inputError';
import { allFiniteNonNegative, isotropic, loadIes, spot, totalFlux, uniformRoom } from './bakeTestKit';
import { withHeadlessGL } from './withHeadlessGL';

const gl = withHeadlessGL();
const baker = createBaker(gl);
const lampAt = (photometry: ReturnType<typeof isotropic>, position: [number, number, number], pitch = 0) => ({ photometry, position, yaw: 0, pitch, roll: 0 });

describe('extremes stay finite and non-negative', () => {
  it('lamp 1 mm from a wall (and 10⁶ cd): finite, flux still conserved in a black room', () => {
    const ph = isotropic(1e6);
    const { maps } = baker.bake({ room: uniformRoom(2, 2, 2, 0), luminaires: [lampAt(ph, [1, 1, 0.001])] }, { texelSize: 0.05, texelSupersampling: 1 });
    expect(allFiniteNonNegative(maps)).toBe(true);
    // Texel centres (texelSupersampling 1): the nearest (2.5 cm off-axis each way) see I·cosθ/d² = I·0.001/d³ ≈ 2.3·10⁷ lx:
    // far beyond half floats (65 504), exact in float32.
    const d = Math.hypot(0.025, 0.025, 0.001);
    expect(Math.max(...maps.north.direct) / ((1e6 * 0.001) / d ** 3)).toBeCloseTo(1, 4);
    // Σ E·A misses the singular peak on the near wall (midpoint rule); the far walls are exact.
    const phi = integrateFlux(ph);
    const far = totalFlux(maps, 'direct') - totalFluxOf(maps.north);
    expect(far / (phi / 2)).toBeGreaterThan(0.95);
  });

  it('lamp 1 mm from a wall with interreflection', () => {
    const { maps } = baker.bake({ room: uniformRoom(3, 2.5, 3, 0.7), luminaires: [lampAt(loadIes('bega_6340_wall_up_down_long_lines.ies'), [0.001, 1.8, 1.5], 90)] }, { texelSize: 0.1, samples: 16 });
    expect(allFiniteNonNegative(maps)).toBe(true);
  });

  it('0.2 m room', () => {
    const { maps, report } = baker.bake({ room: uniformRoom(0.2, 0.2, 0.2, 0.8), luminaires: [lampAt(isotropic(10), [0.1, 0.1, 0.1])] }, { texelSize: 0.01, samples: 16 });
    expect(allFiniteNonNegative(maps)).toBe(true);
    expect(report.texels.floor).toEqual([20, 20]);
  });

  it('100 m hall: texture size capped, finite', () => {
    const { maps, report } = baker.bake({ room: uniformRoom(100, 12, 100, 0.5), luminaires: [lampAt(loadIes('interlight_ovni_highbay_latin1_361v.ies'), [50, 11.5, 50])] }, { texelSize: 0.025, maxTextureSize: 128, samples: 8, bounces: 2 });
    expect(allFiniteNonNegative(maps)).toBe(true);
    expect(report.texels.floor).toEqual([128, 128]);
    expect(report.texels.north).toEqual([128, 128]);
  });

  it('1° spot (sampled every 0.1°) hits the floor in a disc of the right radius', () => {
    const ph = spot(1e5, 0.5, 0.5, 0.1);
    const { maps } = baker.bake({ room: uniformRoom(2, 3, 2, 0.5), luminaires: [lampAt(ph, [1, 3, 1])] }, { texelSize: 0.01, samples: 8, bounces: 1 });
    expect(allFiniteNonNegative(maps)).toBe(true);
    // On axis: E = I/h² = 10⁵/9.
    const floor = maps.floor;
    const centre = (100 * 200 + 100) * 3;
    const texelE = floor.direct[centre];
    const expected = 1e5 / (3 * 3 + 2 * 0.005 ** 2);
    expect(Math.abs(texelE - expected) / expected).toBeLessThan(0.01);
    // Beyond 1° from the axis (3·tan 1° = 5.2 cm) there is no direct light.
    const outside = (100 * 200 + 100 + 7) * 3;
    expect(floor.direct[outside]).toBe(0);
  });

  it('zero lamps: all maps zero, no indirect work', () => {
    const { maps, report } = baker.bake({ room: uniformRoom(4, 3, 5, 0.5), luminaires: [] }, { texelSize: 0.2 });
    expect(allFiniteNonNegative(maps)).toBe(true);
    expect(Math.max(...maps.floor.total, ...maps.ceiling.total)).toBe(0);
    expect(report.indirectEnabled).toBe(false);
  });

  it('a lamp outside the room is rejected with a message naming the field', () => {
    const scene = {
      version: 1,
      room: { width: 5, height: 2.8, depth: 4, reflectance: { floor: 0.2, ceiling: 0.8, north: 0.5, south: 0.5, west: 0.5, east: 0.5 } },
      luminaires: [
        { photometry: 'a.ies', position: [2, 2, 2], yaw: 0, pitch: 0, roll: 0 },
        { photometry: 'a.ies', position: [2, 2, 4.5], yaw: 0, pitch: 0, roll: 0 },
      ],
    };
    expect(() => parseLightingScene(scene, 'scene.json')).toThrow(InputError);
    expect(() => parseLightingScene(scene, 'scene.json')).toThrow('scene.json: luminaires[1].position[2]: 4.5 m is beyond the south wall (z = depth 4 m): luminaires must be inside the room');
  });
});

function totalFluxOf(m: { layout: { lengthU: number; lengthV: number; width: number; height: number }; direct: Float32Array }): number {
  const a = (m.layout.lengthU / m.layout.width) * (m.layout.lengthV / m.layout.height);
  let s = 0;
  for (let i = 0; i < m.direct.length; i += 3) s += m.direct[i + 1] * a;
  return s;
}
