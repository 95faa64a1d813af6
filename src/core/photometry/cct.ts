import { InputError } from '../inputError';
import { CIE1931_2DEG, CIE1931_START_NM, CIE1931_STEP_NM } from './cieCmf1931';

/** A colour temperature outside what cctToLinearRgb covers. */
export class ColorTemperatureError extends InputError {
  override name = 'ColorTemperatureError';
}

export const CCT_MIN_K = 1000;
export const CCT_MAX_K = 20000;

/** Second radiation constant c2 = hc/k in m·K (CIE 15:2004 §B, 1.4388 × 10⁻² m·K). */
const C2 = 1.4388e-2;

/**
 * CIE 1931 XYZ of a blackbody at `kelvin`, normalised to Y = 1: Planck's law
 * M(λ, T) ∝ λ⁻⁵ / (exp(c2 / λT) − 1) (the constant factor cancels in the
 * normalisation) summed against the 5 nm colour-matching functions.
 */
export function planckianXyz(kelvin: number): [number, number, number] {
  checkKelvin(kelvin);
  let x = 0;
  let y = 0;
  let z = 0;
  CIE1931_2DEG.forEach(([xb, yb, zb], i) => {
    const lambda = (CIE1931_START_NM + CIE1931_STEP_NM * i) * 1e-9;
    const m = Math.pow(lambda, -5) / Math.expm1(C2 / (lambda * kelvin));
    x += m * xb;
    y += m * yb;
    z += m * zb;
  });
  return [x / y, 1, z / y];
}

/**
 * Linear sRGB of blackbody light at `kelvin` (1000–20000 K), with unit
 * luminance: XYZ (above) → linear sRGB with the IEC 61966-2-1 matrix (D65
 * white, Rec. 709 primaries). Below about 1900 K and above about 10 000 K the
 * Planckian locus leaves the sRGB gamut and a component comes out negative
 * (blue at 1000 K); such components are clamped to 0, and the result is
 * rescaled so its luminance 0.2126 R + 0.7152 G + 0.0722 B is exactly 1 again.
 */
export function cctToLinearRgb(kelvin: number): [number, number, number] {
  const [X, Y, Z] = planckianXyz(kelvin);
  const r = Math.max(0, 3.2406 * X - 1.5372 * Y - 0.4986 * Z);
  const g = Math.max(0, -0.9689 * X + 1.8758 * Y + 0.0415 * Z);
  const b = Math.max(0, 0.0557 * X - 0.204 * Y + 1.057 * Z);
  const luminance = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  return [r / luminance, g / luminance, b / luminance];
}

function checkKelvin(kelvin: number): void {
  if (!Number.isFinite(kelvin) || kelvin < CCT_MIN_K || kelvin > CCT_MAX_K) {
    throw new ColorTemperatureError(`colour temperature ${kelvin} K is outside ${CCT_MIN_K}–${CCT_MAX_K} K`);
  }
}
