/**
 * A lighting scene's daylight (core/model/lightingScene, docs/daylight.md "The contract") as the
 * baker takes it: the sky, sun and ground from daylightConditions, and each window opening's
 * glazing (what the scene wrote, else DEFAULT_TRANSMITTANCE, "double"). Null without a sky or
 * without a shaped room: nothing of daylight is baked.
 */
import { glazingFrom, type Glazing } from '../../../core/daylight/glazing';
import { groundLuminance } from '../../../core/daylight/skies';
import { daylightConditions, type DaylightConditions } from '../../../core/model/lightingScene/daylightConditions';
import type { LightingScene } from '../../../core/model/lightingScene/lightingScene';
import { DEFAULT_TRANSMITTANCE, type SceneSky } from '../../../core/model/lightingScene/parseDaylight';
import type { BakeDaylight } from './bakeDaylight';

export function bakeDaylightOf(scene: LightingScene): { daylight: BakeDaylight; conditions: DaylightConditions } | null {
  const sky = scene.daylight?.sky;
  const shape = scene.room.shape;
  if (!sky || !shape) return null;
  return bakeDaylightFor(sky, scene);
}

/** Each window opening's glazing: what the scene wrote, else DEFAULT_TRANSMITTANCE. */
function windowGlazing(scene: LightingScene): Map<number, Glazing> {
  const glazing = new Map<number, Glazing>();
  for (const o of scene.room.shape?.openings ?? []) {
    if (o.kind === 'window') glazing.set(o.inputIndex, glazingFrom(scene.daylight?.transmittance[o.inputIndex] ?? DEFAULT_TRANSMITTANCE));
  }
  return glazing;
}

/** The daylight of `scene`'s windows under `sky` (another sky than the scene's: the daylight factor's overcast one). */
export function bakeDaylightFor(sky: SceneSky, scene: LightingScene): { daylight: BakeDaylight; conditions: DaylightConditions } {
  const conditions = daylightConditions(sky);
  const groundL = groundLuminance(conditions.skyHorizontalIlluminance, conditions.sunHorizontalIlluminance, conditions.groundReflectance);
  return {
    conditions,
    daylight: { sky: conditions.sky, sun: conditions.sun, groundLuminance: groundL, glazing: windowGlazing(scene), groundReflectance: conditions.groundReflectance },
  };
}

/**
 * The windows of a shaped room whose daylight has no sky (the sun down, daylight off, or glazing
 * written without a sky): no light comes in (sky and sun null, a dark ground), but the panes know
 * their glazing and the daylight factor its windows and ground (docs/daylight.md). Null without a
 * shape or without daylight; bakeDaylightOf's when there is a sky.
 */
export function darkWindowsOf(scene: LightingScene): BakeDaylight | null {
  const d = scene.daylight;
  if (!d || d.sky || !scene.room.shape) return null;
  return { sky: null, sun: null, groundLuminance: 0, glazing: windowGlazing(scene), ...(d.groundReflectance !== undefined ? { groundReflectance: d.groundReflectance } : {}) };
}
