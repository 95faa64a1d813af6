import { SURFACE_NAMES, type Rgb } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';

/**
 * The area-weighted mean illuminance (RGB lux) over the room's six surfaces: each surface's texels
 * are equal in area, so its mean times its area. What lights the luminaires' housings
 * (docs/viewer.md, "Luminaires"); for a room of any shape, its surfaces in the atlas. An empty room gives 0.
 */
export function meanIlluminance(lit: LitMaps): Rgb {
  const sum: Rgb = [0, 0, 0];
  let area = 0;
  for (const name of SURFACE_NAMES) {
    const layout = lit.layouts[name];
    if (layout.sink) continue;
    const total = lit.maps[name]?.total;
    const n = layout.width * layout.height;
    if (!total || n === 0) continue;
    const a = layout.lengthU * layout.lengthV;
    const mean: Rgb = [0, 0, 0];
    for (let i = 0; i < n; i++) for (let k = 0; k < 3; k++) mean[k] += total[i * 3 + k];
    for (let k = 0; k < 3; k++) sum[k] += (mean[k] / n) * a;
    area += a;
  }
  // A shaped room's surfaces are in the atlas (shapedRoom/encloseShapedRoom.ts): every covered texel by its area, furniture with them.
  const objects = lit.layouts.floor.sink ? lit.maps.objects : undefined;
  if (objects) {
    const { atlas, total } = objects;
    const s2 = atlas.texelSize * atlas.texelSize;
    for (let t = 0; t < atlas.width * atlas.height; t++) {
      const a = atlas.position[4 * t + 3] * s2;
      if (!(a > 0)) continue;
      for (let k = 0; k < 3; k++) sum[k] += total[3 * t + k] * a;
      area += a;
    }
  }
  return area > 0 ? (sum.map((s) => (Number.isFinite(s) ? s / area : 0)) as Rgb) : [0, 0, 0];
}
