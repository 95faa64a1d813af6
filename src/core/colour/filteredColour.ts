/**
 * Colorimetry of a white module behind a colour filter (CIE 15:2004, §7: tristimulus values as
 * sums over the spectrum at 5 nm): source spectrum S(λ) (Planck's law at the module's CCT) times
 * the filter's transmittance τ(λ), summed against the CIE 1931 2° colour-matching functions →
 * X, Y, Z; the luminous transmittance τ_v = Y_filtered / Y_source; chromaticity x = X/(X+Y+Z),
 * y = Y/(X+Y+Z); linear sRGB for the baker with the same matrix, clamping and luminance scaling as
 * cctToLinearRgb, so an unfiltered module keeps exactly today's colour and a filtered one carries
 * its lumen loss in the colour's luminance (0.2126 R + 0.7152 G + 0.0722 B = τ_v).
 */
import { cctToLinearRgb, planckianXyz } from '../photometry/cct';
import { CIE1931_2DEG, CIE1931_START_NM, CIE1931_STEP_NM } from '../photometry/cieCmf1931';
import { cctAndDuv, type CctDuv } from './cctDuv';

/** Second radiation constant c2 = hc/k in m·K (CIE 15:2004, 1.4388 × 10⁻² m·K), as planckianXyz uses. */
const C2 = 1.4388e-2;

export interface FilteredColour {
  /** Tristimulus values of the filtered light, scaled so the unfiltered source has Y = 1 (so Y = τ_v). */
  readonly xyz: readonly [number, number, number];
  /** Luminous transmittance τ_v, 0..1: the fraction of the module's lumens that pass the filter. */
  readonly transmission: number;
  /** CIE 1931 chromaticity. */
  readonly x: number;
  readonly y: number;
  /** Linear sRGB (D65, Rec. 709 primaries) with luminance τ_v: what the baker and relighting take. */
  readonly linearRgb: readonly [number, number, number];
  /** CCT and Duv (Ohno 2014) when the result is near white (|Duv| ≤ NEAR_WHITE_DUV, CCT 1000–20000 K); otherwise null. */
  readonly white: CctDuv | null;
}

/** Spectral radiant exitance of a blackbody on the CMF grid, arbitrary scale (Planck's law, CIE 15:2004). */
export function planckSpectrum(kelvin: number): number[] {
  return CIE1931_2DEG.map((_, i) => {
    const lambda = (CIE1931_START_NM + CIE1931_STEP_NM * i) * 1e-9;
    return Math.pow(lambda, -5) / Math.expm1(C2 / (lambda * kelvin));
  });
}

/** Σ S(λ)·x̄(λ) etc. over the CMF grid (5 nm, 380–780 nm). */
export function spectrumXyz(spectrum: readonly number[]): [number, number, number] {
  let X = 0;
  let Y = 0;
  let Z = 0;
  CIE1931_2DEG.forEach(([xb, yb, zb], i) => {
    X += spectrum[i] * xb;
    Y += spectrum[i] * yb;
    Z += spectrum[i] * zb;
  });
  return [X, Y, Z];
}

/**
 * XYZ → linear sRGB with the IEC 61966-2-1 matrix, negative components (outside the sRGB gamut:
 * saturated gels, deep blues) clamped to 0 and the rest rescaled so the luminance stays Y, as
 * cctToLinearRgb does for the Planckian locus. Y = 0 gives black.
 */
export function xyzToLinearSrgb([X, Y, Z]: readonly [number, number, number]): [number, number, number] {
  const r = Math.max(0, 3.2406 * X - 1.5372 * Y - 0.4986 * Z);
  const g = Math.max(0, -0.9689 * X + 1.8758 * Y + 0.0415 * Z);
  const b = Math.max(0, 0.0557 * X - 0.204 * Y + 1.057 * Z);
  const luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  if (!(luminance > 0) || !(Y > 0)) return [0, 0, 0];
  const k = Y / luminance;
  return [r * k, g * k, b * k];
}

/**
 * The colour of a white module at `kelvin` behind a filter whose transmittance on the CMF grid is
 * `transmission` (transmissionOnCmfGrid), or unfiltered when it is null.
 */
export function filteredColour(kelvin: number, transmission: readonly number[] | null): FilteredColour {
  if (transmission === null) {
    const xyz = planckianXyz(kelvin);
    const s = xyz[0] + xyz[1] + xyz[2];
    return { xyz, transmission: 1, x: xyz[0] / s, y: xyz[1] / s, linearRgb: cctToLinearRgb(kelvin), white: nearWhite(xyz[0] / s, xyz[1] / s) };
  }
  if (transmission.length !== CIE1931_2DEG.length) throw new RangeError(`a transmission curve on the CMF grid has ${CIE1931_2DEG.length} values, not ${transmission.length}`);
  planckianXyz(kelvin); // the same range check (1000–20000 K) and error as the unfiltered path
  const source = planckSpectrum(kelvin);
  const [, Ys] = spectrumXyz(source);
  const [X, Y, Z] = spectrumXyz(source.map((s, i) => s * transmission[i]));
  const xyz: [number, number, number] = [X / Ys, Y / Ys, Z / Ys];
  const sum = xyz[0] + xyz[1] + xyz[2];
  // A filter that passes nothing visible (none in the library does) has no chromaticity.
  const [x, y] = sum > 0 ? [xyz[0] / sum, xyz[1] / sum] : [NaN, NaN];
  return { xyz, transmission: xyz[1], x, y, linearRgb: xyzToLinearSrgb(xyz), white: sum > 0 ? nearWhite(x, y) : null };
}

/**
 * Largest |Duv| still called white: ANSI C78.377 bins white LEDs within ±0.006 of the locus;
 * we report CCT a little further out (±0.02), where a tinted white (CTO + a green shift) still
 * reads as white, and say nothing beyond, where CCT stops meaning a colour (Ohno 2014, §1).
 */
export const NEAR_WHITE_DUV = 0.02;

function nearWhite(x: number, y: number): CctDuv | null {
  const r = cctAndDuv(x, y);
  return r !== null && Math.abs(r.duv) <= NEAR_WHITE_DUV ? r : null;
}
