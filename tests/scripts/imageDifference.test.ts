import { describe, expect, it } from 'vitest';
import { cropImage, imageDifference, withinTolerance } from '../../e2e-engines/imageDifference';

/** A w×h RGBA image whose pixel i has the colour colourOf(i). */
function image(width: number, height: number, colourOf: (i: number) => [number, number, number]) {
  const data = new Uint8Array(width * height * 4);
  for (let i = 0; i < width * height; i++) data.set([...colourOf(i), 255], 4 * i);
  return { width, height, data };
}

describe('imageDifference (the furnished goldens’ metric, e2e-engines/imageDifference.ts)', () => {
  it('is zero for identical images', () => {
    const a = image(4, 3, (i) => [i, 2 * i, 3 * i]);
    expect(imageDifference(a, a)).toEqual({ mean: 0, p50: 0, p90: 0, p99: 0, max: 0 });
  });

  it('takes the largest channel difference per pixel; mean and nearest-rank percentiles by hand', () => {
    // 10 pixels: differences 0, 1, …, 9 in one channel each (R, G or B in turn), alpha ignored.
    const a = image(10, 1, () => [100, 100, 100]);
    const b = image(10, 1, (i) => [100 + (i % 3 === 0 ? i : 0), 100 - (i % 3 === 1 ? i : 0), 100 + (i % 3 === 2 ? i : 0)]);
    const d = imageDifference(a, b);
    expect(d.mean).toBeCloseTo(4.5, 12);
    // Nearest rank: p50 = the 5th smallest (4), p90 the 9th (8), p99 and max the 10th (9).
    expect([d.p50, d.p90, d.p99, d.max]).toEqual([4, 8, 9, 9]);
  });

  it('refuses images of different sizes', () => {
    expect(() =>
      imageDifference(
        image(2, 2, () => [0, 0, 0]),
        image(2, 3, () => [0, 0, 0]),
      ),
    ).toThrow(/2×2 and 2×3/);
  });

  it('a tolerance bounds the mean and the 90th percentile, not the edges', () => {
    const d = { mean: 0.5, p50: 0, p90: 1, p99: 60, max: 200 };
    expect(withinTolerance(d, { mean: 1.5, p90: 3 })).toBe(true);
    expect(withinTolerance({ ...d, mean: 2 }, { mean: 1.5, p90: 3 })).toBe(false);
    expect(withinTolerance({ ...d, p90: 4 }, { mean: 1.5, p90: 3 })).toBe(false);
  });

  it('crops a rectangle row by row and refuses one outside the image', () => {
    const img = image(4, 3, (i) => [i, 0, 0]);
    const c = cropImage(img, { x: 1, y: 1, width: 2, height: 2 });
    expect([c.width, c.height]).toEqual([2, 2]);
    expect([c.data[0], c.data[4], c.data[8], c.data[12]]).toEqual([5, 6, 9, 10]);
    expect(() => cropImage(img, { x: 3, y: 0, width: 2, height: 1 })).toThrow(/outside/);
  });
});
