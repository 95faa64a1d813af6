import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { texelArea } from '../bake/surfaceLayout';
import { SURFACE_NAMES, type Rgb, type SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { LitMaps } from '../relight/relightMaps';
import type { ObjectLight } from './objectLight';

/** Scene value that auto exposure maps the room's average luminance to (photographic middle grey). */
export const AUTO_EXPOSURE_KEY = 0.18;

/** Luminance below this (cd/m²) counts as this in the log average: black texels must not drive exposure to infinity. */
const FLOOR_LUMINANCE = 1e-3;

/**
 * Automatic exposure: the key value over the area-weighted log-average
 * luminance of the six surfaces, L = ρ·E/π (Reinhard et al., "Photographic
 * Tone Reproduction", SIGGRAPH 2002, eq. 1): robust to a bright spot on a
 * wall. The objects count with their area too: each covered atlas texel weighs
 * its coverage × texel² and has its own ρ (the G-buffer's), so a room full of
 * dark furniture is exposed for what the eye sees. Returns 1/(cd/m²); a dark
 * room (no light) gets 1.
 */
export function autoExposure(lit: LitMaps, reflectance: Record<SurfaceName, Rgb>, objects: ObjectLight | null = null): number {
  let logSum = 0;
  let area = 0;
  let any = false;
  for (const name of SURFACE_NAMES) {
    // A shaped room's enclosure: the six box surfaces are sinks, its surfaces are in the atlas.
    if (lit.layouts[name].sink) continue;
    const rgb = lit.maps[name].total;
    const a = texelArea(lit.layouts[name]);
    const rho = reflectance[name];
    for (let i = 0; i < rgb.length; i += 3) {
      const L = (LUMINANCE_WEIGHTS[0] * rho[0] * rgb[i] + LUMINANCE_WEIGHTS[1] * rho[1] * rgb[i + 1] + LUMINANCE_WEIGHTS[2] * rho[2] * rgb[i + 2]) / Math.PI;
      if (L > FLOOR_LUMINANCE) any = true;
      logSum += Math.log(Math.max(L, FLOOR_LUMINANCE)) * a;
      area += a;
    }
  }
  if (objects) {
    const { atlas, total } = objects;
    const s2 = atlas.texelSize * atlas.texelSize;
    for (let t = 0; t < atlas.width * atlas.height; t++) {
      const a = atlas.position[4 * t + 3] * s2;
      if (!(a > 0)) continue;
      const r = atlas.reflectance;
      const L = (LUMINANCE_WEIGHTS[0] * r[4 * t] * total[3 * t] + LUMINANCE_WEIGHTS[1] * r[4 * t + 1] * total[3 * t + 1] + LUMINANCE_WEIGHTS[2] * r[4 * t + 2] * total[3 * t + 2]) / Math.PI;
      if (L > FLOOR_LUMINANCE) any = true;
      logSum += Math.log(Math.max(L, FLOOR_LUMINANCE)) * a;
      area += a;
    }
  }
  if (!any || area === 0) return 1;
  return AUTO_EXPOSURE_KEY / Math.exp(logSum / area);
}
