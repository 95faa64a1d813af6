/**
 * The crossfade between two light scenes (docs/light-scenes.md, "Crossfade"): one fade fraction
 * e(t) for every module, output levels (1 − e)·from + e·to. Mixing the outputs linearly is a
 * console's "dipless" crossfade (a module at the same level in both scenes does not move), and
 * it keeps the light linear in e, so the 3D view blends the two scenes' solved light exactly.
 *
 * The easing: e(t) is chosen so the room's perceived brightness changes evenly in time. Perceived
 * brightness is CIE 1976 lightness L* of the total luminous output Y relative to the brighter
 * scene (CIE 15:2004, §8.2.1: L* = 116 f(Y/Yn) − 16, f(x) = x^(1/3) above (6/29)³, linear below),
 * interpolated linearly in t and turned back into Y:
 *
 *   L*(t) = (1 − t)·L*(Y_from/Yn) + t·L*(Y_to/Yn),   Yn = max(Y_from, Y_to)
 *   e(t)  = (Yn·L*⁻¹(L*(t)) − Y_from) / (Y_to − Y_from)        (e(t) = t when Y_from = Y_to)
 *
 * A fade up from black then starts slowly (e ≈ t³ once out of L*'s linear toe), as a theatre
 * dimmer's square-law curve (output ∝ level²) does for the same reason, and a fade to black drops
 * quickly first; both look even to the eye, which linear output does not. Between scenes of equal
 * output e = t (the dipless linear crossfade).
 */
import { findBeam, findModuleType, type Catalog } from './catalogSchema';
import type { Configuration } from './configuration';
import { allModules } from './lightScenes';

const DELTA = 6 / 29;

/** CIE 1976 lightness of a relative luminance y = Y/Yn in [0, 1]: 0..100. */
export function lightness(y: number): number {
  const f = y > DELTA ** 3 ? Math.cbrt(y) : y / (3 * DELTA * DELTA) + 4 / 29;
  return 116 * f - 16;
}

/** Relative luminance of a lightness (the inverse of lightness()). */
export function luminanceOfLightness(l: number): number {
  const f = (l + 16) / 116;
  return f > DELTA ? f ** 3 : 3 * DELTA * DELTA * (f - 4 / 29);
}

/** Total luminous output of a configuration, lumens: Σ over modules that are on of level × the beam's lumens. */
export function luminousOutput(config: Configuration, catalog: Catalog): number {
  let y = 0;
  for (const m of allModules(config)) if (m.on !== false) y += m.dimming * findBeam(findModuleType(catalog, m.type), m.beam).lumens;
  return y;
}

/** The fade fraction e at time fraction t ∈ [0, 1] between outputs yFrom and yTo (lumens): even steps of L*. */
export function fadeFraction(t: number, yFrom: number, yTo: number): number {
  const u = Math.min(1, Math.max(0, t));
  const yn = Math.max(yFrom, yTo);
  if (u === 0 || u === 1 || !(yn > 0) || Math.abs(yTo - yFrom) <= 1e-9 * yn) return u;
  const l = (1 - u) * lightness(yFrom / yn) + u * lightness(yTo / yn);
  const e = (yn * luminanceOfLightness(l) - yFrom) / (yTo - yFrom);
  return Math.min(1, Math.max(0, e));
}

/** Each module's output level (0 when off) shown at fade fraction e: (1 − e)·from + e·to; modules of `to` only. */
export function fadeLevels(from: Configuration, to: Configuration, e: number): Map<string, number> {
  const before = new Map(allModules(from).map((m) => [m.id, m.on === false ? 0 : m.dimming]));
  const out = new Map<string, number>();
  for (const m of allModules(to)) {
    const b = m.on === false ? 0 : m.dimming;
    const a = before.get(m.id) ?? b;
    out.set(m.id, (1 - e) * a + e * b);
  }
  return out;
}
