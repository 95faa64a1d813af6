import type { Rgb, Vec3 } from '../../core/model/lightingScene/lightingScene';
import { intensity } from '../../core/photometry/intensity';
import { photometricAngles, transpose, applyMat3 } from './luminaireRotation';
import type { LampSources } from './scenePointSources';

/**
 * Direct illuminance (lux, RGB) exactly at a surface point p with unit normal n,
 * on the CPU in float64: E = Σ I(γ, C)·cos(incidence)/d² over the same point
 * sources the direct pass uses (CIE 171:2006 §5.2), each, when `visible` is
 * given (a scene with objects), only if the point sees it. `luxbox probe` takes direct light from here, not from the maps:
 * near a hot spot E changes by orders of magnitude between texel centres,
 * where any interpolation of a map is wrong.
 */
export function directAtPoint(lamps: readonly LampSources[], p: Vec3, n: Vec3, visible?: (p: Vec3, n: Vec3, source: Vec3) => boolean): Rgb {
  const out: Rgb = [0, 0, 0];
  for (const lamp of lamps) {
    const toLocal = transpose(lamp.rotation);
    let e = 0;
    for (let k = 0; k < lamp.sources.length; k++) {
      const s = lamp.sources[k];
      const d: Vec3 = [p[0] - s[0], p[1] - s[1], p[2] - s[2]];
      const d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      if (!(d2 > 1e-24)) continue;
      const dist = Math.sqrt(d2);
      const cos = -(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) / dist;
      if (!(cos > 0)) continue;
      const local = applyMat3(toLocal, d);
      // A face of a tall opening emits only its own hemisphere (openingSources).
      if (lamp.sides[k] * local[1] < 0) continue;
      // With objects: only sources the point sees past them (the direct pass's shadow test).
      if (visible && !visible(p, n, s)) continue;
      const [g, c] = photometricAngles(local);
      e += (Math.max(0, intensity(lamp.photometry, g, c)) * cos) / d2;
    }
    for (let c = 0; c < 3; c++) out[c] += lamp.weight[c] * e;
  }
  return out;
}
