/**
 * Statistics on the GPU (createGpuStats.ts, shaders/statsReduce.glsl.ts) against hand sums on the
 * CPU (statsOf over the photometric Y of the counted texels, as floorStats does), in headless-gl:
 * Ē within 1e-5 relative (a float32 sum of up to 65 536 values), Emin and Emax within 1e-6, the
 * number of texels exact. The floor maps come from the GPU relight, so the whole chain reads back
 * 16 bytes per request and no map.
 */
import { describe, expect, it } from 'vitest';
import { LUMINANCE_WEIGHTS } from '../../../src/engines/bake/bakedMaps';
import { createFloatTarget, deleteTarget, uploadRgb } from '../../../src/engines/bake/floatTarget';
import { surfaceLayouts } from '../../../src/engines/bake/surfaceLayout';
import { createGpuRelight } from '../../../src/engines/relight/createGpuRelight';
import { emptyLitMaps, relightMaps, type DirectBasis, type WeightedBasis } from '../../../src/engines/relight/relightMaps';
import { createGpuStats, type PendingStats } from '../../../src/engines/view/createGpuStats';
import { floorStats, statsOf, type IlluminanceStats } from '../../../src/engines/view/lightStats';
import { createRng } from '../../fuzz/mutate';
import { withHeadlessGL } from '../bake/withHeadlessGL';

const gl = withHeadlessGL();
const random = createRng(340).next;

/** Hand sums: Y = 0.2126 R + 0.7152 G + 0.0722 B of every texel not covered. */
function handStats(rgb: Float32Array, covered: Uint8Array | null): IlluminanceStats {
  const y: number[] = [];
  for (let i = 0; i < rgb.length / 3; i++) if (!covered?.[i]) y.push(LUMINANCE_WEIGHTS[0] * rgb[i * 3] + LUMINANCE_WEIGHTS[1] * rgb[i * 3 + 1] + LUMINANCE_WEIGHTS[2] * rgb[i * 3 + 2]);
  return statsOf(y);
}

/** The GPU has finished once gl.finish returns, so the first poll after it answers. */
function settled(pending: PendingStats): IlluminanceStats {
  gl.finish();
  const stats = pending.poll();
  if (!stats) throw new Error('the fence had not signalled after gl.finish');
  return stats;
}

function expectClose(gpu: IlluminanceStats, hand: IlluminanceStats) {
  expect(gpu.points).toBe(hand.points);
  expect(Math.abs(gpu.avg - hand.avg)).toBeLessThanOrEqual(1e-5 * hand.avg);
  expect(Math.abs(gpu.min - hand.min)).toBeLessThanOrEqual(1e-6 * hand.max);
  expect(Math.abs(gpu.max - hand.max)).toBeLessThanOrEqual(1e-6 * hand.max);
  expect(Math.abs(gpu.u0 - hand.u0)).toBeLessThanOrEqual(2e-5 * Math.max(hand.u0, 1e-3));
}

describe('GPU statistics = hand sums', () => {
  it.each([
    [60, 70],
    [300, 37],
    [256, 256],
  ])('a %i × %i map, a covered rectangle and scattered covered texels left out', (width, height) => {
    const rgb = Float32Array.from({ length: width * height * 3 }, () => 5 + 800 * random() * random());
    const covered = new Uint8Array(width * height);
    for (let j = 0; j < height; j++) for (let i = 0; i < width; i++) covered[j * width + i] = (i > width / 3 && i < width / 2 && j > 3 && j < height / 2) || random() < 0.05 ? 1 : 0;
    // The darkest and the brightest texel lie under furniture: a CPU that forgot the mask would see them.
    covered[5 * width + Math.floor(width / 3) + 2] = 1;
    rgb.fill(0.01, (5 * width + Math.floor(width / 3) + 2) * 3, (5 * width + Math.floor(width / 3) + 3) * 3);
    const stats = createGpuStats(gl);
    const map = createFloatTarget(gl, width, height, false);
    try {
      uploadRgb(gl, map, rgb);
      expectClose(settled(stats.request(map, covered)), handStats(rgb, covered));
      expectClose(settled(stats.request(map, null)), handStats(rgb, null));
      expect(stats.readbacks).toEqual({ count: 2, bytes: 32 });
    } finally {
      stats.dispose();
      deleteTarget(gl, map);
    }
  });

  it('everything covered: no points, all zero (as statsOf of nothing)', () => {
    const stats = createGpuStats(gl);
    const map = createFloatTarget(gl, 8, 8, false);
    try {
      expect(settled(stats.request(map, new Uint8Array(64).fill(1)))).toEqual({ avg: 0, min: 0, max: 0, u0: 0, points: 0 });
    } finally {
      stats.dispose();
      deleteTarget(gl, map);
    }
  });

  it('the floor of a GPU relight: the same numbers as floorStats of the CPU relight, no map read back', () => {
    const layouts = surfaceLayouts({ width: 3, height: 2.5, depth: 2 }, 0.05, 256);
    const lit = emptyLitMaps(layouts);
    const map = (n: number) => Float32Array.from({ length: n * 3 }, () => 300 * random());
    const basis = (): DirectBasis => ({ surfaces: Object.fromEntries(layouts.map((l) => [l.name, map(l.width * l.height)])) as DirectBasis['surfaces'], flux: [1, 1, 1] });
    const parts: WeightedBasis[] = [basis(), basis(), basis()].map((b, i) => ({ basis: b, weight: [0.3 * (i + 1), 0.5, 1 - 0.2 * i] }));
    const solution = { surfaces: basis().surfaces, flux: [1, 1, 1] as [number, number, number], key: 'k', final: true };
    const terms = [{ solution, scale: [0.8, 0.9, 1.1] as [number, number, number] }];
    const relight = createGpuRelight(gl);
    const stats = createGpuStats(gl);
    try {
      const gpuMaps = relight.relight(parts, terms, lit.layouts, null);
      const gpu = settled(stats.request(gpuMaps.floor.total, null));
      expectClose(gpu, floorStats(relightMaps(parts, terms, null, lit)));
      expect(relight.readbacks.count).toBe(0);
      expect(stats.readbacks).toEqual({ count: 1, bytes: 16 });
    } finally {
      relight.dispose();
      stats.dispose();
    }
  });
});
