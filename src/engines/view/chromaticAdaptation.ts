/**
 * How the viewer adapts the scene's light to the display white (docs/viewer.md, "Adaptation"):
 *
 * - `eye` (default): CAT16 from the scene's adopted white (adoptedWhite.ts) to D65 with the
 *   CIECAM02/CAM16 degree of adaptation D at the adapting luminance L_A, so a 2700 K room stays
 *   warm but not orange and a 4000 K office looks nearly neutral;
 * - `camera` white balance at a CCT: CAT16 with D = 1 from that CCT's white (cctToLinearRgb);
 * - `none`: the physical linear RGB (what the viewer showed before).
 *
 * L_A: 20 % of the adapting white's luminance, the usual choice for CIECAM02 when nothing better is
 * known (Moroney et al., "The CIECAM02 color appearance model", IS&T/SID CIC 10, 2002; Fairchild,
 * Color Appearance Models, 3rd ed., §16), the white being estimated as the luminance the
 * auto exposure puts at white: the log-average scene luminance L̄ (autoExposure.ts) is middle grey
 * (0.18), so L_w = L̄ / 0.18 and L_A = 0.2 · L̄ / 0.18 = 0.2 / autoExposure.
 */
import { cctToLinearRgb } from '../../core/photometry/cct';
import type { AdaptationSetting } from './adaptationSetting';
import { AUTO_EXPOSURE_KEY } from './autoExposure';
import { cat16LinearSrgb, degreeOfAdaptation, IDENTITY3 } from './cat16';
import type { Mat3, Vec3 } from './colourMatrices';

/** Share of the adapting white's luminance taken as L_A (CIECAM02 practice: 20 %). */
export const ADAPTING_WHITE_SHARE = 0.2;

/** L_A (cd/m²) for an automatic exposure `auto` (1/(cd/m²)): 0.2 × the white L̄/0.18 (see above). */
export function adaptingLuminance(auto: number): number {
  if (!(auto > 0) || !Number.isFinite(auto)) return 0;
  const logAverage = AUTO_EXPOSURE_KEY / auto;
  return ADAPTING_WHITE_SHARE * (logAverage / AUTO_EXPOSURE_KEY);
}

export interface Adaptation {
  /** Row-major 3×3 on linear sRGB, applied to luminance before the tone curve. */
  matrix: Mat3;
  /** The degree of adaptation used (0 for none). */
  d: number;
  /** The white adapted from (linear sRGB, luminance 1), or null: none. */
  white: Vec3 | null;
}

/** The adaptation matrix for a setting, the scene's adopted white (null: no white lamp) and the adapting luminance L_A (cd/m²). */
export function adaptationFor(setting: AdaptationSetting, sceneWhite: Vec3 | null, la: number): Adaptation {
  if (setting.kind === 'none') return { matrix: IDENTITY3, d: 0, white: null };
  if (setting.kind === 'camera') {
    const white = cctToLinearRgb(setting.cct);
    return { matrix: cat16LinearSrgb(white, 1), d: 1, white };
  }
  if (!sceneWhite) return { matrix: IDENTITY3, d: 0, white: null };
  const d = degreeOfAdaptation(la);
  return { matrix: cat16LinearSrgb(sceneWhite, d), d, white: sceneWhite };
}
