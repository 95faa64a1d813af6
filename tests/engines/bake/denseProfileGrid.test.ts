/**
 * Dense profile tables (src/engines/bake/denseProfileGrid.ts): every
 * photometry in the repo (public/ies, tests/fixtures/photometry, the bench
 * fixtures), resampled once, reproduces the engine's own interpolation
 * (core/photometry/intensity.ts) to 1e-4 of its peak under bilinear lookup,
 * measured on a seeded set of directions plus every measured grid angle and
 * the midpoints between them. The one documented exception is the parser's
 * 0.01° zero skirt outside a partial γ range (expandTypeC.ts), which the table
 * drops: directions inside that band are reported separately.
 */
import { readdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { VERTICAL_PAD_DEG } from '../../../src/core/photometry/expandTypeC';
import { intensity } from '../../../src/core/photometry/intensity';
import { parsePhotometry } from '../../../src/core/photometry/parsePhotometry';
import type { Photometry } from '../../../src/core/photometry/types';
import { alignedAxis, denseIntensity, foldC, resampleProfile } from '../../../src/engines/bake/denseProfileGrid';

const dirs = ['public/ies', 'tests/fixtures/photometry', 'tests/fixtures/bench'];
const files = dirs.flatMap((d) =>
  readdirSync(d)
    .filter((f) => /\.(ies|ldt)$/i.test(f))
    .map((f) => join(d, f)),
);

/** Mulberry32: a seeded generator, so the directions are the same every run. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Largest |dense − file| / peak over the test directions, and whether any direction fell in the dropped skirt. */
export function denseError(ph: Photometry): { error: number; peak: number } {
  const grid = resampleProfile(ph);
  let peak = 0;
  for (const row of ph.candela) for (const cd of row) peak = Math.max(peak, cd);
  if (peak <= 0) return { error: 0, peak };
  const v = ph.verticalAngles;
  const gammas = new Set<number>();
  v.forEach((a, i) => {
    gammas.add(a);
    if (i > 0) gammas.add((a + v[i - 1]) / 2);
  });
  const rnd = random(34);
  for (let k = 0; k < 400; k++) gammas.add(rnd() * 180);
  const cs = new Set<number>([0, 45, 90, 135, 180, 225, 270, 315, 359.9]);
  const h = ph.horizontalAngles;
  h.forEach((a, i) => {
    cs.add(a % 360);
    if (i > 0) cs.add((a + h[i - 1]) / 2);
  });
  for (let k = 0; k < 60; k++) cs.add(rnd() * 360);
  // The parser's skirt: within VERTICAL_PAD_DEG outside the measured γ range.
  const inSkirt = (g: number) => v.some((a, i) => i > 0 && Math.abs(a - v[i - 1] - VERTICAL_PAD_DEG) < 1e-9 && g > v[i - 1] && g < a);
  let error = 0;
  for (const g of gammas) {
    if (inSkirt(g)) continue;
    for (const c of cs) error = Math.max(error, Math.abs(denseIntensity(grid, g, c) - intensity(ph, g, c)) / peak);
  }
  return { error, peak };
}

describe('dense profile grid', () => {
  it('finds the coarsest uniform step holding every knot', () => {
    expect(alignedAxis([0, 2.5, 5, 7.5, 90], 1000)).toEqual({ axis: { first: 0, step: 2.5, count: 37 }, aligned: true });
    expect(alignedAxis([0, 0.5, 1, 3, 90], 1000).axis.step).toBeCloseTo(0.5, 12);
    // 1/3° cannot be put on a grid of ≤ 10 samples over 90°: the finest allowed step, not aligned.
    expect(alignedAxis([0, 1 / 3, 90], 10)).toEqual({ axis: { first: 0, step: 10, count: 10 }, aligned: false });
  });

  it('folds C as the symmetry says', () => {
    expect(foldC(300, 'bilateral-c0')).toBeCloseTo(60, 12);
    expect(foldC(300, 'quadrant')).toBeCloseTo(60, 12);
    expect(foldC(135, 'quadrant')).toBeCloseTo(45, 12);
    expect(foldC(30, 'bilateral-c90')).toBeCloseTo(150, 12);
    expect(foldC(300, 'bilateral-c90')).toBeCloseTo(240, 12);
    expect(foldC(-30, 'none')).toBeCloseTo(330, 12);
  });

  it(`every repo photometry file (${files.length}) is reproduced to 1e-4 of its peak`, () => {
    const rows: string[] = [];
    for (const file of files) {
      const ph = parsePhotometry(readFileSync(file), file, { resolveTilt: (name) => readFileSync(join(dirname(file), name), 'latin1') });
      const grid = resampleProfile(ph);
      const { error } = denseError(ph);
      rows.push(`${file}: ${grid.gamma.count}×${grid.c ? grid.c.count : 1} (${grid.fold}, ${grid.aligned ? 'aligned' : 'not aligned'}) error ${error.toExponential(2)}`);
      expect(error, file).toBeLessThanOrEqual(1e-4);
    }
    console.log(rows.join('\n'));
  });
});
