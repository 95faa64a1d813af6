/**
 * Veiling glare: the light the eye's media scatter around a bright source (docs/viewer.md, "Glare").
 * The point-spread function is the CIE General Disability Glare equation (CIE 146:2002, "CIE
 * equations for disability glare"; J. J. Vos, "On the cause of disability glare and its dependence
 * on glare angle, age and ocular pigmentation", Clin. Exp. Optom. 86(6):363–370, 2003):
 *
 *   L_veil / E_glare = 10/θ³ + (5/θ² + 0.1·p/θ)·(1 + (A/62.5)⁴) + 0.0025·p   [sr⁻¹, θ in degrees]
 *
 * valid for 0.1° < θ < 100°: the veiling luminance a point source of illuminance E at the eye adds
 * at an angle θ from it. As a PSF of the image (luminance in, luminance out) it is the fraction of
 * a pixel's light that lands per steradian at θ, so the share landing in an annulus [a, b] is
 * ∫ PSF · 2πθ dθ (small-angle, θ in radians). The image-space idea is Spencer, Shirley, Zimmerman,
 * Greenberg, "Physically-based glare effects for digital images", SIGGRAPH 1995: convolve the
 * linear image with the eye's PSF before the display maps it.
 */

/** The observer: age in years (the equation's A) and ocular pigmentation p (0 black, 0.5 brown, 1 blue-green eyes). */
export const GLARE_OBSERVER = { age: 40, pigmentation: 0.5 } as const;

const RAD2 = (Math.PI / 180) ** 2;

/** L_veil / E_glare in sr⁻¹ at θ degrees (CIE 146:2002 General Disability Glare equation). */
export function cieGlarePsf(thetaDeg: number, observer: { age: number; pigmentation: number } = GLARE_OBSERVER): number {
  const t = thetaDeg;
  const ageFactor = 1 + (observer.age / 62.5) ** 4;
  return 10 / t ** 3 + (5 / t ** 2 + (0.1 * observer.pigmentation) / t) * ageFactor + 0.0025 * observer.pigmentation;
}

/** The share of a point's light the PSF sends into the annulus a…b degrees from it: ∫ PSF(θ)·2πθ dθ, exactly (θ in radians for the solid angle). */
export function annulusShare(aDeg: number, bDeg: number, observer: { age: number; pigmentation: number } = GLARE_OBSERVER): number {
  if (!(bDeg > aDeg) || !(aDeg > 0)) return 0;
  const ageFactor = 1 + (observer.age / 62.5) ** 4;
  const p = observer.pigmentation;
  const twoPi = 2 * Math.PI;
  const integral = twoPi * 10 * (1 / aDeg - 1 / bDeg) + twoPi * 5 * ageFactor * Math.log(bDeg / aDeg) + twoPi * 0.1 * p * ageFactor * (bDeg - aDeg) + Math.PI * 0.0025 * p * (bDeg * bDeg - aDeg * aDeg);
  return integral * RAD2;
}

/** Where the equation holds (CIE 146:2002): the PSF is used only within it. */
export const GLARE_MIN_DEG = 0.1;
export const GLARE_MAX_DEG = 100;

/**
 * The PSF discretised for the glare pass's pyramid: level k (k = 1…levels, 2^k × coarser than the
 * image) spreads light over a radius of about 2^k pixels, so it carries the annulus
 * 2^(k−½) … 2^(k+½) pixels (the last level also what lies beyond, up to the image's diagonal);
 * `core` is what stays in the pixel: the light within 2^½ pixels plus the part of the PSF outside
 * the equation's domain or the image. core + Σ levels = 1: the pass moves light, it never adds or
 * removes any. `pixelDeg`: the angle one pixel subtends (vertical field / height in pixels).
 */
export function glareWeights(pixelDeg: number, levels: number, diagonalPx: number, observer: { age: number; pigmentation: number } = GLARE_OBSERVER): { core: number; levels: number[] } {
  const weights: number[] = [];
  if (!(pixelDeg > 0) || !(levels > 0)) return { core: 1, levels: weights };
  const clampDeg = (px: number) => Math.min(GLARE_MAX_DEG, Math.max(GLARE_MIN_DEG, px * pixelDeg));
  for (let k = 1; k <= levels; k++) {
    const inner = 2 ** (k - 0.5);
    const outer = k === levels ? Math.max(2 ** (k + 0.5), diagonalPx) : 2 ** (k + 0.5);
    weights.push(annulusShare(clampDeg(inner), clampDeg(outer), observer));
  }
  const scattered = weights.reduce((s, w) => s + w, 0);
  return { core: 1 - scattered, levels: weights };
}

/** How many levels the pyramid of a W×H image gets: halvings while the smallest side stays ≥ 4 pixels, at most 8. */
export function glareLevels(width: number, height: number): number {
  return Math.max(0, Math.min(8, Math.floor(Math.log2(Math.min(width, height) / 4))));
}
