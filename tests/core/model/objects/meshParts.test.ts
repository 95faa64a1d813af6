/**
 * Ringed solids (meshParts.ts ringedPart, slabRings, ellipsoidRings) against closed forms: a
 * straight prism of rounded-rectangle rings has the volume of its ring polygon × height, a
 * bevelled slab keeps its stated bounds exactly, and an ellipsoid's rings lie on the ellipsoid.
 */
import { describe, expect, it } from 'vitest';
import { positionBounds } from '../../../../src/core/mesh/triangleMesh';
import { ellipsoidRings, ringedPart, slabRings, type MeshPart } from '../../../../src/core/model/objects/furniture/meshParts';

function signedVolume(part: MeshPart): number {
  const p = part.positions;
  let v = 0;
  for (let t = 0; t < part.indices.length; t += 3) {
    const [a, b, c] = [part.indices[t] * 3, part.indices[t + 1] * 3, part.indices[t + 2] * 3];
    v += p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) - p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) + p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return v / 6;
}

describe('ringed parts', () => {
  it('a prism of two equal rounded-rectangle rings: volume = polygon area × height (1e-12), for k = 1, 2, 5', () => {
    for (const k of [1, 2, 5]) {
      const [hx, hz, r, h] = [0.4, 0.25, 0.1, 0.3];
      const part = ringedPart(
        'p',
        0.2,
        -0.1,
        [
          [0, hx, hz, r],
          [h, hx, hz, r],
        ],
        k,
      );
      // The ring: a rectangle with each corner cut by a k-segment chord polygon of the quarter circle.
      const sector = k * 0.5 * r * r * Math.sin(Math.PI / 2 / k); // k triangles from the arc centre
      const area = 2 * hx * (2 * hz) - 4 * r * r + 4 * sector;
      expect(Math.abs(signedVolume(part) - area * h)).toBeLessThan(1e-12);
    }
  });

  it('a circle ring (r = hx = hz) has 4k distinct points; a stadium (r = hx < hz) 4k + 2', () => {
    const circle = ringedPart(
      'c',
      0,
      0,
      [
        [0, 0.1, 0.1, 0.1],
        [1, 0.1, 0.1, 0.1],
      ],
      3,
    );
    expect(circle.positions.length / 3).toBe(2 * 12 + 2);
    const stadium = ringedPart(
      's',
      0,
      0,
      [
        [0, 0.1, 0.2, 0.1],
        [1, 0.1, 0.2, 0.1],
      ],
      3,
    );
    expect(stadium.positions.length / 3).toBe(2 * 14 + 2);
  });

  it('a bevelled, leaning slab keeps its bounds: widest ring exactly hx × hz, y from y0 to y1, the lean added at the top', () => {
    const part = ringedPart('s', 0, 0, slabRings(0.3, 0.8, 0.5, 0.2, 0.08, 0.05, 0.03, -0.1), 1);
    const b = positionBounds(part.positions);
    expect([b.min[0], b.max[0], b.min[1], b.max[1]]).toEqual([-0.5, 0.5, 0.3, 0.8]);
    expect(b.min[2]).toBeCloseTo(-0.2 - 0.1 * ((0.8 - 0.05 - 0.3) / 0.5), 12);
    expect(b.max[2]).toBeCloseTo(0.2 - 0.1 * (0.03 / 0.5), 12); // the lowest full-size ring, just above the bottom bevel
  });

  it('ellipsoid rings lie on the ellipsoid (x/hx)² + ((y − yc)/ay)² = 1 at their widest points', () => {
    for (const [y, hx, hz] of ellipsoidRings(1.2, 0.3, 0.2, 0.1, 4)) {
      expect((hx / 0.2) ** 2 + ((y - 1.2) / 0.3) ** 2).toBeCloseTo(1, 12);
      expect((hz / 0.1) ** 2 + ((y - 1.2) / 0.3) ** 2).toBeCloseTo(1, 12);
    }
  });

  it('refuses a corner radius larger than the ring and rings of different shapes', () => {
    expect(() => ringedPart('x', 0, 0, [[0, 0.1, 0.1, 0.2]])).toThrow(/corner radius/);
    expect(() =>
      ringedPart('x', 0, 0, [
        [0, 0.1, 0.1, 0.1],
        [1, 0.2, 0.1, 0.1],
      ]),
    ).toThrow(/differ in shape/);
  });
});
