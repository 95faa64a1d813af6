import { describe, expect, it } from 'vitest';
import fc from 'fast-check';
import type { Vec3 } from '../../src/core/model/lightingScene/lightingScene';
import { BOX_FACES, makePatchGrid } from '../../src/reference/boxGeometry';
import { buildFaceKernels, patchFormFactor } from '../../src/reference/formFactorKernels';
import { pointToPolygonFormFactor } from '../../src/reference/pointToPolygonFormFactor';
import { parallelExchangeArea, perpendicularExchangeArea } from '../../src/reference/rectangleExchangeArea';

// 8-point Gauss–Legendre nodes/weights on [−1, 1] (Abramowitz & Stegun table 25.4).
const GL8_X = [-0.9602898564975363, -0.7966664774136267, -0.525532409916329, -0.1834346424956498, 0.1834346424956498, 0.525532409916329, 0.7966664774136267, 0.9602898564975363];
const GL8_W = [0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.362683783378362, 0.362683783378362, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763];

/** ∫_A1 F(dA → polygon) dA by composite 8×8 Gauss–Legendre over an m×m split: an independent route to A1·F12. */
function quadratureExchangeArea(corner: (s: number, t: number) => Vec3, n: Vec3, sLen: number, tLen: number, polygon: Vec3[], m = 6): number {
  let sum = 0;
  for (let a = 0; a < m; a++) {
    for (let b = 0; b < m; b++) {
      for (let i = 0; i < 8; i++) {
        for (let j = 0; j < 8; j++) {
          const s = ((a + 0.5 + 0.5 * GL8_X[i]) / m) * sLen;
          const t = ((b + 0.5 + 0.5 * GL8_X[j]) / m) * tLen;
          sum += GL8_W[i] * GL8_W[j] * 0.25 * pointToPolygonFormFactor(corner(s, t), n, polygon);
        }
      }
    }
  }
  return (sum * sLen * tLen) / (m * m);
}

describe('exact rectangle-to-rectangle exchange areas', () => {
  it('reproduce tabulated view factors of unit squares (Howell catalog C-11, C-14)', () => {
    // Directly opposed unit squares one unit apart: F = 0.19982; sharing an edge at 90°: F = 0.20004.
    expect(parallelExchangeArea(0, 1, 0, 1, 0, 1, 0, 1, 1)).toBeCloseTo(0.199825, 6);
    expect(perpendicularExchangeArea(0, 1, 0, 1, 0, 1, 0, 1)).toBeCloseTo(0.200044, 6);
    // The directly-opposed closed form (Howell C-11) for a 2 × 0.5 pair 0.7 apart.
    const X = 2 / 0.7;
    const Y = 0.5 / 0.7;
    const c11 =
      (2 / (Math.PI * X * Y)) *
      (0.5 * Math.log(((1 + X * X) * (1 + Y * Y)) / (1 + X * X + Y * Y)) +
        X * Math.sqrt(1 + Y * Y) * Math.atan(X / Math.sqrt(1 + Y * Y)) +
        Y * Math.sqrt(1 + X * X) * Math.atan(Y / Math.sqrt(1 + X * X)) -
        X * Math.atan(X) -
        Y * Math.atan(Y));
    expect(parallelExchangeArea(0, 2, 0, 0.5, 0, 2, 0, 0.5, 0.7) / 1).toBeCloseTo(c11 * 1, 12);
  });

  it('agree with quadrature of the point-to-polygon contour integral (offset parallel and perpendicular pairs)', () => {
    // Parallel: rect 1 = [0,1]×[0.5,2] at z=0, rect 2 = [1.3,2]×[−1,0.2] at z=0.7.
    const par = parallelExchangeArea(0, 1, 0.5, 2, 1.3, 2, -1, 0.2, 0.7);
    const parQ = quadratureExchangeArea((s, t) => [s, 0.5 + t, 0], [0, 0, 1], 1, 1.5, [
      [1.3, -1, 0.7],
      [2, -1, 0.7],
      [2, 0.2, 0.7],
      [1.3, 0.2, 0.7],
    ]);
    expect(Math.abs(par - parQ) / par).toBeLessThan(1e-8);
    // Perpendicular: rect 1 = x∈[0,1], y∈[0.5,2] in z=0; rect 2 = x∈[1.3,2], z∈[0.1,0.4] in y=0.
    const perp = perpendicularExchangeArea(0, 1, 0.5, 2, 1.3, 2, 0.1, 0.4);
    const perpQ = quadratureExchangeArea((s, t) => [s, 0.5 + t, 0], [0, 0, 1], 1, 1.5, [
      [1.3, 0, 0.1],
      [2, 0, 0.1],
      [2, 0, 0.4],
      [1.3, 0, 0.4],
    ]);
    expect(Math.abs(perp - perpQ) / perp).toBeLessThan(1e-8);
  });

  it('are reciprocal: A1F12 = A2F21 (random rectangles)', () => {
    const interval = fc.tuple(fc.double({ min: -3, max: 3, noNaN: true }), fc.double({ min: 0.05, max: 2, noNaN: true }));
    const positive = fc.tuple(fc.double({ min: 0, max: 3, noNaN: true }), fc.double({ min: 0.05, max: 2, noNaN: true }));
    fc.assert(
      fc.property(interval, interval, interval, interval, fc.double({ min: 0.1, max: 4, noNaN: true }), (x, y, xi, eta, c) => {
        const a = parallelExchangeArea(x[0], x[0] + x[1], y[0], y[0] + y[1], xi[0], xi[0] + xi[1], eta[0], eta[0] + eta[1], c);
        const b = parallelExchangeArea(xi[0], xi[0] + xi[1], eta[0], eta[0] + eta[1], x[0], x[0] + x[1], y[0], y[0] + y[1], c);
        return a > 0 && Math.abs(a - b) <= 1e-9 * a + 1e-14;
      }),
      { seed: 7, numRuns: 200 },
    );
    fc.assert(
      fc.property(interval, positive, interval, positive, (x, y, xi, eta) => {
        const a = perpendicularExchangeArea(x[0], x[0] + x[1], y[0], y[0] + y[1], xi[0], xi[0] + xi[1], eta[0], eta[0] + eta[1]);
        const b = perpendicularExchangeArea(xi[0], xi[0] + xi[1], eta[0], eta[0] + eta[1], x[0], x[0] + x[1], y[0], y[0] + y[1]);
        return a > 0 && Math.abs(a - b) <= 1e-9 * a + 1e-14;
      }),
      { seed: 8, numRuns: 200 },
    );
  });
});

describe('point-to-polygon form factor (Lambert contour integral)', () => {
  it('matches the closed form for a parallel rectangle with a corner above the element (Howell B-3)', () => {
    for (const [a, b, c] of [
      [1, 1, 1],
      [2, 0.5, 0.7],
      [0.1, 3, 2],
    ]) {
      const X = a / c;
      const Y = b / c;
      const exact = (1 / (2 * Math.PI)) * ((X / Math.sqrt(1 + X * X)) * Math.atan(Y / Math.sqrt(1 + X * X)) + (Y / Math.sqrt(1 + Y * Y)) * Math.atan(X / Math.sqrt(1 + Y * Y)));
      const f = pointToPolygonFormFactor(
        [0, 0, 0],
        [0, 0, 1],
        [
          [0, 0, c],
          [a, 0, c],
          [a, b, c],
          [0, b, c],
        ],
      );
      expect(f).toBeCloseTo(exact, 13);
    }
  });

  it('sums to 1 over the five other faces of a box, from anywhere on a face', () => {
    const W = 5;
    const H = 2.7;
    const D = 4;
    for (const [x, z] of [
      [2.5, 2],
      [0.001, 3.999],
      [4.9, 0.3],
    ]) {
      const p: Vec3 = [x, 0, z];
      const faces: Vec3[][] = [
        [
          [0, H, 0],
          [W, H, 0],
          [W, H, D],
          [0, H, D],
        ],
        [
          [0, 0, 0],
          [W, 0, 0],
          [W, H, 0],
          [0, H, 0],
        ],
        [
          [0, 0, D],
          [W, 0, D],
          [W, H, D],
          [0, H, D],
        ],
        [
          [0, 0, 0],
          [0, 0, D],
          [0, H, D],
          [0, H, 0],
        ],
        [
          [W, 0, 0],
          [W, 0, D],
          [W, H, D],
          [W, H, 0],
        ],
      ];
      const sum = faces.reduce((s, f) => s + pointToPolygonFormFactor(p, [0, 1, 0], f), 0);
      expect(Math.abs(sum - 1)).toBeLessThan(1e-12);
    }
  });
});

describe('box patch kernels', () => {
  const grid = makePatchGrid([5, 2.7, 4], 0.3);
  const kernels = buildFaceKernels(grid);
  const counts = BOX_FACES.map((f) => grid.count[f.uAxis] * grid.count[f.vAxis]);
  const area = (p: number): number => grid.size[BOX_FACES[p].uAxis] * grid.size[BOX_FACES[p].vAxis];

  it('close the box: every patch row sums to 1 (to 1e-10)', () => {
    let worst = 0;
    for (let p = 0; p < 6; p++) {
      for (let i = 0; i < counts[p]; i++) {
        let sum = 0;
        for (let q = 0; q < 6; q++) for (let j = 0; j < counts[q]; j++) sum += patchFormFactor(grid, kernels, p, i, q, j);
        worst = Math.max(worst, Math.abs(sum - 1));
      }
    }
    expect(worst).toBeLessThan(1e-10);
  });

  it('are reciprocal patch by patch: A_i F_ij = A_j F_ji (to 1e-12 relative: derived, not recomputed)', () => {
    let worst = 0;
    for (let p = 0; p < 6; p++) {
      for (let q = 0; q < 6; q++) {
        if (p === q) continue;
        for (let i = 0; i < counts[p]; i += 7) {
          for (let j = 0; j < counts[q]; j += 5) {
            const a = area(p) * patchFormFactor(grid, kernels, p, i, q, j);
            const b = area(q) * patchFormFactor(grid, kernels, q, j, p, i);
            worst = Math.max(worst, Math.abs(a - b) / Math.max(a, 1e-300));
          }
        }
      }
    }
    expect(worst).toBeLessThan(1e-12);
  });

  it('give per-face sums equal to the exact face-to-face factor (floor → ceiling of a 5 × 4 × 2.7 room)', () => {
    // Patch-weighted sum over floor patches of F(i → ceiling) = F(floor → ceiling), the closed form C-11.
    const floor = 0;
    const ceiling = 1;
    let sum = 0;
    for (let i = 0; i < counts[floor]; i++) for (let j = 0; j < counts[ceiling]; j++) sum += patchFormFactor(grid, kernels, floor, i, ceiling, j);
    const exact = parallelExchangeArea(0, 5, 0, 4, 0, 5, 0, 4, 2.7) / 20;
    expect(sum / counts[floor]).toBeCloseTo(exact, 10);
  });
});
