import { SURFACE_NAMES, type Rgb } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';

/**
 * The area-weighted mean illuminance (RGB lux) over the room's six surfaces: each surface's texels
 * are equal in area, so its mean times its area. What lights the luminaires' housings
 * (docs/viewer.md, "Luminaires"). An empty room gives 0.
 */
export function meanIlluminance(lit: LitMaps): Rgb {
  const sum: Rgb = [0, 0, 0];
  let area = 0;
  for (const name of SURFACE_NAMES) {
    const layout = lit.layouts[name];
    const total = lit.maps[name]?.total;
    const n = layout.width * layout.height;
    if (!total || n === 0) continue;
    const a = layout.lengthU * layout.lengthV;
    const mean: Rgb = [0, 0, 0];
    for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) mean[k] += total[i * 3 + k];
    for (let k = 0; k < 3; k++) sum[k] += (mean[k] / n) * a;
    area += a;
  }
  return area > 0 ? (sum.map((s) => (Number.isFinite(s) ? s / area : 0)) as Rgb) : [0, 0, 0];
}
