import type { BakedMaps } from '../../../src/engines/bake/bakedMaps';
import { luxOf } from '../../../src/engines/bake/bakedMaps';

/** The four walls: where the eye-height and corner views look, and where blotches read as dirt. */
export const WALLS = ['north', 'south', 'west', 'east'] as const;

/** The monomials u^a·v^b with a + b ≤ 3 (a bicubic-by-degree surface, 10 terms). */
function monomials(u: number, v: number): number[] {
  const out: number[] = [];
  for (let a = 0; a <= 3; a++) for (let b = 0; a + b <= 3; b++) out.push(u ** a * v ** b);
  return out;
}

/** Solve A x = y (small, dense, symmetric positive definite) by Gaussian elimination with partial pivoting. */
function solve(a: number[][], y: number[]): number[] {
  const n = y.length;
  const m = a.map((row, i) => [...row, y[i]]);
  for (let c = 0; c < n; c++) {
    let pivot = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(m[r][c]) > Math.abs(m[pivot][c])) pivot = r;
    [m[c], m[pivot]] = [m[pivot], m[c]];
    for (let r = c + 1; r < n; r++) {
      const f = m[r][c] / m[c][c];
      for (let k = c; k <= n; k++) m[r][k] -= f * m[c][k];
    }
  }
  const x = new Array<number>(n).fill(0);
  for (let r = n - 1; r >= 0; r--) {
    let s = m[r][n];
    for (let k = r + 1; k < n; k++) s -= m[r][k] * x[k];
    x[r] = s / m[r][r];
  }
  return x;
}

/**
 * The least-squares cubic fit of a map of lux (w × h texels, row-major): the smooth part of the
 * field. Coordinates are texel centres scaled to [−1, 1] so the normal equations stay well conditioned.
 */
export function cubicFit(lux: Float32Array, w: number, h: number): Float64Array {
  const basis: number[][] = [];
  for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) basis.push(monomials(((i + 0.5) / w) * 2 - 1, ((j + 0.5) / h) * 2 - 1));
  const n = basis[0].length;
  const ata = Array.from({ length: n }, () => new Array<number>(n).fill(0));
  const aty = new Array<number>(n).fill(0);
  basis.forEach((row, t) => {
    for (let p = 0; p < n; p++) {
      aty[p] += row[p] * lux[t];
      for (let q = 0; q < n; q++) ata[p][q] += row[p] * row[q];
    }
  });
  const coefficients = solve(ata, aty);
  return Float64Array.from(basis, (row) => row.reduce((s, m, p) => s + m * coefficients[p], 0));
}

/**
 * Blotchiness: per wall the RMS of the indirect illuminance about its cubic fit, relative to the
 * wall's mean indirect illuminance; combined over the walls weighted by their texel counts.
 */
export function wallBlotchiness(maps: BakedMaps): number {
  let squares = 0;
  let count = 0;
  for (const wall of WALLS) {
    const { layout, indirect } = maps[wall];
    const lux = luxOf(indirect);
    const fit = cubicFit(lux, layout.width, layout.height);
    const mean = lux.reduce((s, x) => s + x, 0) / lux.length;
    for (let t = 0; t < lux.length; t++) squares += ((lux[t] - fit[t]) / mean) ** 2;
    count += lux.length;
  }
  return Math.sqrt(squares / count);
}

/** RMS of the walls' indirect illuminance against a reference bake's, relative to each wall's reference mean. */
export function wallDeviation(maps: BakedMaps, reference: BakedMaps): number {
  let squares = 0;
  let count = 0;
  for (const wall of WALLS) {
    const lux = luxOf(maps[wall].indirect);
    const ref = luxOf(reference[wall].indirect);
    const mean = ref.reduce((s, x) => s + x, 0) / ref.length;
    for (let t = 0; t < lux.length; t++) squares += ((lux[t] - ref[t]) / mean) ** 2;
    count += lux.length;
  }
  return Math.sqrt(squares / count);
}
