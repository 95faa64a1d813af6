import type { Rgb } from '../../core/model/lightingScene/lightingScene';
import { LUMINANCE_WEIGHTS } from './bakedMaps';
import type { SurfaceLayout } from './surfaceLayout';

/** Bilinear lookup between texel centres (clamped at the borders) of an RGB map at surface coordinates (u, v) in metres. */
export function bilinearRgb(layout: SurfaceLayout, rgb: Float32Array, u: number, v: number): Rgb {
  const fx = Math.min(layout.width - 1, Math.max(0, (u / layout.lengthU) * layout.width - 0.5));
  const fy = Math.min(layout.height - 1, Math.max(0, (v / layout.lengthV) * layout.height - 0.5));
  const x0 = Math.floor(fx);
  const y0 = Math.floor(fy);
  const x1 = Math.min(layout.width - 1, x0 + 1);
  const y1 = Math.min(layout.height - 1, y0 + 1);
  const tx = fx - x0;
  const ty = fy - y0;
  const out: Rgb = [0, 0, 0];
  for (let c = 0; c < 3; c++) {
    const a = rgb[(y0 * layout.width + x0) * 3 + c] * (1 - tx) + rgb[(y0 * layout.width + x1) * 3 + c] * tx;
    const b = rgb[(y1 * layout.width + x0) * 3 + c] * (1 - tx) + rgb[(y1 * layout.width + x1) * 3 + c] * tx;
    out[c] = a * (1 - ty) + b * ty;
  }
  return out;
}

/** Bilinear lookup of an RGB map, as lux (photometric Y; Y is linear in RGB, so interpolating first is exact). */
export function bilinearLux(layout: SurfaceLayout, rgb: Float32Array, u: number, v: number): number {
  const [r, g, b] = bilinearRgb(layout, rgb, u, v);
  return LUMINANCE_WEIGHTS[0] * r + LUMINANCE_WEIGHTS[1] * g + LUMINANCE_WEIGHTS[2] * b;
}
