import { PNG } from 'pngjs';

/** An RGBA image, rows top first (pngjs's layout). */
export interface RgbaImage {
  width: number;
  height: number;
  data: Uint8Array | Buffer;
}

/**
 * How two pictures of the same view differ, per pixel the largest of |ΔR|, |ΔG|, |ΔB| in 0–255
 * display levels: the mean over the image and the 50th, 90th and 99th percentiles and the maximum.
 * The mean and the 90th percentile say whether the picture is the same (exposure, white, light,
 * camera); the 99th percentile and the maximum are the edges, where engines rasterise and
 * anti-alias differently (docs/viewer.md, "Furnished goldens").
 */
export interface ImageDifference {
  mean: number;
  p50: number;
  p90: number;
  p99: number;
  max: number;
}

/** The two images must have the same size; the error names both. */
export function imageDifference(a: RgbaImage, b: RgbaImage): ImageDifference {
  if (a.width !== b.width || a.height !== b.height) throw new Error(`images differ in size: ${a.width}×${a.height} and ${b.width}×${b.height}`);
  const n = a.width * a.height;
  // A histogram of the 256 possible differences gives exact percentiles without sorting n values.
  const histogram = new Float64Array(256);
  let sum = 0;
  for (let i = 0; i < n; i++) {
    const k = 4 * i;
    const d = Math.max(Math.abs(a.data[k] - b.data[k]), Math.abs(a.data[k + 1] - b.data[k + 1]), Math.abs(a.data[k + 2] - b.data[k + 2]));
    histogram[d]++;
    sum += d;
  }
  const percentile = (f: number) => {
    const rank = Math.ceil(f * n);
    let seen = 0;
    for (let d = 0; d < 256; d++) {
      seen += histogram[d];
      if (seen >= rank) return d;
    }
    return 255;
  };
  return { mean: n > 0 ? sum / n : 0, p50: percentile(0.5), p90: percentile(0.9), p99: percentile(0.99), max: percentile(1) };
}

/** The rectangle (CSS pixels = image pixels at device pixel ratio 1) cut out of a screenshot. */
export function cropImage(image: RgbaImage, rect: { x: number; y: number; width: number; height: number }): PNG {
  const { x, y, width, height } = rect;
  if (x < 0 || y < 0 || x + width > image.width || y + height > image.height) {
    throw new Error(`crop ${width}×${height} at (${x}, ${y}) lies outside the ${image.width}×${image.height} image`);
  }
  const out = new PNG({ width, height });
  for (let row = 0; row < height; row++) {
    const from = ((y + row) * image.width + x) * 4;
    out.data.set(image.data.subarray(from, from + width * 4), row * width * 4);
  }
  return out;
}

/** A difference within a tolerance: the mean and the 90th percentile both at most the tolerance's. */
export interface GoldenTolerance {
  mean: number;
  p90: number;
}

export function withinTolerance(d: ImageDifference, t: GoldenTolerance): boolean {
  return d.mean <= t.mean && d.p90 <= t.p90;
}

export const formatDifference = (d: ImageDifference) => `mean ${d.mean.toFixed(2)}, p50 ${d.p50}, p90 ${d.p90}, p99 ${d.p99}, max ${d.max} of 255`;
