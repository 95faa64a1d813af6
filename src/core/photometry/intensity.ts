import { bracket } from './convertTypeAB';
import type { Photometry } from './types';

/**
 * Intensity in cd toward (γ, C) in the luminaire frame, bilinear in (γ, C) on
 * the expanded grid. Any angles are accepted: γ outside [0, 180] is reflected
 * through the pole (γ' = −γ or 360 − γ, with C + 180, the same direction), and
 * C is taken modulo 360. The grid's 360 plane equals its 0 plane, so the value
 * is continuous across C = 0/360 and, because the expanded grid holds the
 * mirrored planes, across every symmetry seam (90, 180, 270).
 */
export function intensity(ph: Photometry, gammaDeg: number, cDeg: number): number {
  if (!Number.isFinite(gammaDeg) || !Number.isFinite(cDeg)) return 0;
  let g = ((gammaDeg % 360) + 360) % 360;
  let c = cDeg;
  if (g > 180) {
    g = 360 - g;
    c += 180;
  }
  c = ((c % 360) + 360) % 360;
  const [j0, j1, t] = bracket(ph.verticalAngles, g);
  const rows = ph.candela;
  if (ph.horizontalAngles.length === 1) {
    const row = rows[0];
    return row[j0] * (1 - t) + row[j1] * t;
  }
  const [i0, i1, s] = bracket(ph.horizontalAngles, c);
  const a = rows[i0][j0] * (1 - t) + rows[i0][j1] * t;
  const b = rows[i1][j0] * (1 - t) + rows[i1][j1] * t;
  return a * (1 - s) + b * s;
}
