import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { SURFACE_NAMES } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import { texelArea } from '../bake/surfaceLayout';
import type { ObjectLight } from './objectLight';

/**
 * Top of the false-colour scale: the 99th percentile of texel lux over all six
 * surfaces (not the maximum: a lamp touching a wall makes a tiny hot spot that
 * would push every other surface into the bottom colour). Found with a
 * 1/16-decade log histogram: one pass, no sort, about 15 % resolution.
 * Objects' covered atlas texels count too, each weighing its covered area in
 * units of a wall texel's area (coverage × (atlas texel / floor texel)²), so the
 * percentile is one of area, as on the walls (equal texel areas there).
 */
export function luxScaleTop(lit: LitMaps, percentile = 0.99, objects: ObjectLight | null = null): number {
  const BINS_PER_DECADE = 16;
  const LOW = -3; // 1 mlx
  const bins = new Float64Array(BINS_PER_DECADE * 12);
  let count = 0;
  const bin = (y: number) => Math.min(bins.length - 1, Math.max(0, y > 0 ? Math.floor((Math.log10(y) - LOW) * BINS_PER_DECADE) : 0));
  for (const n of SURFACE_NAMES) {
    // A shaped room's enclosure: the box surfaces are sinks, the room's surfaces are in the atlas.
    if (lit.layouts[n].sink) continue;
    const m = lit.maps[n].total;
    for (let i = 0; i < m.length; i += 3) {
      const y = LUMINANCE_WEIGHTS[0] * m[i] + LUMINANCE_WEIGHTS[1] * m[i + 1] + LUMINANCE_WEIGHTS[2] * m[i + 2];
      bins[bin(y)]++;
      count++;
    }
  }
  if (objects) {
    const weight = (objects.atlas.texelSize * objects.atlas.texelSize) / texelArea(lit.layouts.floor);
    const m = objects.total;
    for (let t = 0; t < objects.atlas.width * objects.atlas.height; t++) {
      const w = objects.atlas.position[4 * t + 3] * weight;
      if (!(w > 0)) continue;
      bins[bin(LUMINANCE_WEIGHTS[0] * m[3 * t] + LUMINANCE_WEIGHTS[1] * m[3 * t + 1] + LUMINANCE_WEIGHTS[2] * m[3 * t + 2])] += w;
      count += w;
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
