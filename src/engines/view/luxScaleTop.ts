import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { SURFACE_NAMES } from '../../core/model/lightingScene';
import type { LitMaps } from '../relight/relightMaps';

/**
 * Top of the false-colour scale: the 99th percentile of texel lux over all six
 * surfaces (not the maximum: a lamp touching a wall makes a tiny hot spot that
 * would push every other surface into the bottom colour). Found with a
 * 1/16-decade log histogram: one pass, no sort, about 15 % resolution.
 */
export function luxScaleTop(lit: LitMaps, percentile = 0.99): number {
  const BINS_PER_DECADE = 16;
  const LOW = -3; // 1 mlx
  const bins = new Uint32Array(BINS_PER_DECADE * 12);
  let count = 0;
  for (const n of SURFACE_NAMES) {
    const m = lit.maps[n].total;
    for (let i = 0; i < m.length; i += 3) {
      const y = LUMINANCE_WEIGHTS[0] * m[i] + LUMINANCE_WEIGHTS[1] * m[i + 1] + LUMINANCE_WEIGHTS[2] * m[i + 2];
      const b = y > 0 ? Math.floor((Math.log10(y) - LOW) * BINS_PER_DECADE) : 0;
      bins[Math.min(bins.length - 1, Math.max(0, b))]++;
      count++;
    }
  }
  if (count === 0) return 1;
  const target = percentile * count;
  let seen = 0;
  for (let b = 0; b < bins.length; b++) {
    seen += bins[b];
    if (seen >= target) return 10 ** (LOW + (b + 1) / BINS_PER_DECADE);
  }
  return 10 ** (LOW + bins.length / BINS_PER_DECADE);
}
