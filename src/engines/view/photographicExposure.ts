/**
 * Absolute (photographic) exposure: an exposure value at ISO 100, EV100,
 * sets which scene luminance saturates the image, independent of the scene.
 *
 * Saturation-based sensitivity (ISO 12232:2006; as used for rendering in
 * Lagarde & de Rousiers, "Moving Frostbite to Physically Based Rendering 3.0",
 * SIGGRAPH 2014 course notes, §5.1.2): the luminance that just saturates the
 * sensor is
 *
 *   L_max = 78 / (S · q) · N²/t,  q = 0.65 (lens and vignetting factor),
 *
 * and with EV100 = log2(N²/t) at S = 100 this is L_max = 1.2 · 2^EV100 cd/m².
 * The viewer multiplies luminance (cd/m²) by its exposure before the display
 * curve (adaptation, AgX, sRGB: toneMap.ts), so a fixed EV100 means the
 * exposure 1 / L_max: a surface at L_max gives the linear value 1.0 before the
 * curve. Reference points: EV100 0 → L_max 1.2 cd/m², EV100 5 → 38.4 cd/m².
 */

/** Calibration factor 78 / (100 · 0.65) of the saturation-based formula at ISO 100 (cd/m² at EV100 = 0). */
export const SATURATION_LUMINANCE_EV0 = 78 / (100 * 0.65);

/** The range the CLI, the viewer and the embed option accept (EV100 −6 is moonlight, 20 direct sun on snow). */
export const EV100_MIN = -6;
export const EV100_MAX = 20;

/** Luminance (cd/m²) that saturates the image at this EV100: 1.2 · 2^EV100. */
export function saturationLuminance(ev100: number): number {
  return SATURATION_LUMINANCE_EV0 * 2 ** ev100;
}

/** The viewer's exposure (multiplier on luminance, 1/(cd/m²)) for a fixed EV100: 1 / L_max. */
export function exposureFromEv100(ev100: number): number {
  return 1 / saturationLuminance(ev100);
}

/** The EV100 that gives this exposure (inverse of exposureFromEv100): what "lock exposure" keeps. */
export function ev100FromExposure(exposure: number): number {
  return Math.log2(1 / (SATURATION_LUMINANCE_EV0 * exposure));
}

/** How a view exposes: 'auto' (key value over the log-average luminance, autoExposure.ts) or a fixed EV100. */
export type ExposureSetting = 'auto' | number;

/** True when `ev` is a finite EV100 in EV100_MIN..EV100_MAX. */
export function isEv100(ev: unknown): ev is number {
  return typeof ev === 'number' && Number.isFinite(ev) && ev >= EV100_MIN && ev <= EV100_MAX;
}
