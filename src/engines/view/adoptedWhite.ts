import { cctAndDuv } from '../../core/colour/cctDuv';
import { NEAR_WHITE_DUV } from '../../core/colour/filteredColour';
import { integrateFlux } from '../../core/photometry/flux';
import type { Photometry } from '../../core/photometry/types';
import type { BakeLuminaire, BakeScene } from '../bake/bakeScene';
import type { Room } from '../../core/room/normaliseRoom';
import type { BakeDaylight } from '../bake/daylight/bakeDaylight';
import type { LightSources } from '../relight/daylightGroups';
import { daylightEnteringFlux } from '../bake/daylight/daylightEnteringFlux';
import { daylightWindows } from '../bake/daylight/daylightWindows';
import { LUMINANCE_WEIGHTS } from '../bake/bakedMaps';
import { SRGB_TO_XYZ, mulVec3, type Vec3 } from './colourMatrices';

const fluxes = new WeakMap<Photometry, number>();
function fluxOf(p: Photometry): number {
  let f = fluxes.get(p);
  if (f === undefined) {
    f = integrateFlux(p);
    fluxes.set(p, f);
  }
  return f;
}

/** Whether a light colour (linear sRGB) is a white: CCT with |Duv| ≤ NEAR_WHITE_DUV (Ohno 2014), as the filter library calls a tint white. */
export function isWhiteLight(rgb: Vec3): boolean {
  const [X, Y, Z] = mulVec3(SRGB_TO_XYZ, rgb);
  const s = X + Y + Z;
  if (!(s > 0) || !(Y > 0)) return false;
  const r = cctAndDuv(X / s, Y / s);
  return r !== null && Math.abs(r.duv) <= NEAR_WHITE_DUV;
}

/**
 * The scene's adopted white for chromatic adaptation: the luminous-flux-weighted mix of the
 * light of its white lamps, Σ Φ_i · dimming_i · colour_i (linear sRGB; a lamp's colour carries its
 * luminous transmittance, so Φ·dimming·Y(colour) is the lumens it emits), normalised to luminance 1.
 * A room of 2700 K and 4000 K modules adapts to their mix, not to each, so their difference stays
 * visible. Lamps behind saturated gels (|Duv| beyond NEAR_WHITE_DUV) are left out: an eye does
 * not take a red stage light for white, and a gel must stay its colour. Null when no white lamp
 * is on (then there is nothing to adapt to). Daylight counts with the lumens it brings in
 * (`daylightLumens`, sceneAdoptedWhite): a room lit mostly through its windows adapts toward
 * daylight's white, and its 2700 K lamps look warm, as they do by day; without it a daylit room
 * adapted to the lamps alone and rendered blue.
 */
export function adoptedWhite(luminaires: readonly BakeLuminaire[], daylightLumens = 0): Vec3 | null {
  // Daylight as the baker carries it is achromatic (equal RGB: D65, the display's own white).
  const day = Number.isFinite(daylightLumens) && daylightLumens > 0 ? daylightLumens : 0;
  const sum = [day, day, day];
  for (const l of luminaires) {
    const d = Math.max(0, l.dimming ?? 1);
    const c = l.color ?? [1, 1, 1];
    if (!(d > 0) || !isWhiteLight(c)) continue;
    const w = fluxOf(l.photometry) * d;
    if (!(w > 0) || !Number.isFinite(w)) continue;
    for (let k = 0; k < 3; k++) sum[k] += w * c[k];
  }
  const y = LUMINANCE_WEIGHTS[0] * sum[0] + LUMINANCE_WEIGHTS[1] * sum[1] + LUMINANCE_WEIGHTS[2] * sum[2];
  if (!(y > 0) || !Number.isFinite(y)) return null;
  return [sum[0] / y, sum[1] / y, sum[2] / y];
}

/**
 * The adopted white of a scene as shown: its white lamps (unless only daylight is shown) and the
 * daylight entering through its windows (unless only the electric light is shown), each weighted by
 * its lumens (daylightEnteringFlux.ts).
 */
export function sceneAdoptedWhite(scene: BakeScene, sources: LightSources = 'both'): Vec3 | null {
  const lamps = sources === 'electric' || sources === 'both' ? scene.luminaires : [];
  const daylight = sources !== 'electric' ? scene.daylight : undefined;
  const shape = scene.room.shape;
  return adoptedWhite(lamps, daylight && shape ? enteringLumens(scene, daylight, shape) : 0);
}

// Per scene object (a new scene is a new object): the maps are shown on every bake slice.
const entering = new WeakMap<BakeScene, number>();
function enteringLumens(scene: BakeScene, daylight: BakeDaylight, shape: Room): number {
  let lm = entering.get(scene);
  if (lm === undefined) {
    lm = daylightEnteringFlux(daylight, daylightWindows(shape, [0, 0, 0], daylight.glazing));
    entering.set(scene, lm);
  }
  return lm;
}
