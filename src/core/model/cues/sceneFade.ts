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
import { findBeam, findModuleType, type Catalog } from '../catalogSchema/catalogSchema';
import type { Configuration } from '../configuration/configuration';
import { allModules } from './lightScenes';
import type { Rgb } from '../lightingScene/lightingScene';

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
  return levelsOutput(outputLevels(config), config, catalog);
}

/**
 * Total luminous output of shown levels (module id → output level, as outputLevels or mixLevels
 * give), lumens: Σ level × the beam's lumens of the configuration's module of that id. Linear in
 * the levels, so the output of a mix is the same mix of the outputs.
 */
export function levelsOutput(levels: ReadonlyMap<string, number>, config: Configuration, catalog: Catalog): number {
  let y = 0;
  for (const m of allModules(config)) y += (levels.get(m.id) ?? 0) * findBeam(findModuleType(catalog, m.type), m.beam).lumens;
  return y;
}

/** Each module's output level: its dimming, 0 when switched off. */
export function outputLevels(config: Configuration): Map<string, number> {
  return new Map(allModules(config).map((m) => [m.id, m.on === false ? 0 : m.dimming]));
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
  return mixLevels(outputLevels(from), outputLevels(to), e);
}

/**
 * Output levels at fade fraction e between two sets of levels: (1 − e)·from + e·to for every
 * module of `to` (one missing from `from` holds its `to` level). A fade that starts from what is
 * shown in the middle of another fade starts from such a mix (a console's cue fades from the
 * current state of the stage, not from the end of the interrupted cue).
 */
export function mixLevels(from: ReadonlyMap<string, number>, to: ReadonlyMap<string, number>, e: number): Map<string, number> {
  const out = new Map<string, number>();
  for (const [id, b] of to) {
    const a = from.get(id) ?? b;
    out.set(id, (1 - e) * a + e * b);
  }
  return out;
}

/** A module's light as the baker weights it: dimming (0..1) and colour (linear RGB, relative). */
export interface ModuleLight {
  readonly dimming: number;
  readonly color: Rgb;
}

/**
 * The lights shown at fade fraction e between two sets of module lights, per module id of `to`.
 * The baker's weight of a module is dimming × colour (RGB), and the crossfade mixes the weights
 * linearly (docs/light-scenes.md), so the mix has weight (1 − e)·d_a·c_a + e·d_b·c_b; it is
 * returned as dimming d = (1 − e)·d_a + e·d_b and colour weight / d (the `to` colour when d = 0,
 * where the colour does not show). A module missing from `from` holds its `to` light.
 */
export function mixLights(from: ReadonlyMap<string, ModuleLight>, to: ReadonlyMap<string, ModuleLight>, e: number): Map<string, ModuleLight> {
  const out = new Map<string, ModuleLight>();
  for (const [id, b] of to) {
    const a = from.get(id) ?? b;
    const d = (1 - e) * a.dimming + e * b.dimming;
    const w = [0, 1, 2].map((k) => (1 - e) * a.dimming * a.color[k] + e * b.dimming * b.color[k]);
    out.set(id, { dimming: d, color: d > 0 ? [w[0] / d, w[1] / d, w[2] / d] : b.color });
  }
  return out;
}
