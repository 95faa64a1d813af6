import { PhotometryParseError } from './PhotometryParseError';
import type { Photometry } from './types';
import type { ExpandedGrid, TypeCGrid } from './expandTypeC';

const EPS = 1e-6;
const DEG = Math.PI / 180;

/**
 * Resolution of the type-C grid that a type A or B file is resampled onto.
 * 0.5° in γ and 1° in C resolve a 5° floodlight beam with ≥ 10 samples across,
 * at 361 × 361 = 130 321 values.
 */
export const TYPE_AB_GAMMA_STEP = 0.5;
export const TYPE_AB_C_STEP = 1;

/**
 * Converts a type A or type B grid (LM-63 photometric type 3 or 2) into the
 * type-C luminaire frame of docs/scene-format.md. The file's aiming axis (H = V = 0)
 * becomes the nadir, so an unrotated floodlight points straight down and the
 * scene's pitch aims it, as its trunnion would.
 *
 * Axes: aim a → local −y, lateral (H > 0, to the right looking along the
 * beam) l → local +x (C0), up (V > 0) u → local −z (C90). This is a proper
 * rotation of the (a, l, u) frame, and pitching the luminaire by +90° (Rx)
 * brings the beam to −z with V > 0 pointing to world +y (the sky), the usual
 * floodlight orientation.
 *
 * For a type-C direction (γ, C): a = cos γ, l = sin γ cos C, u = sin γ sin C.
 *  - Type B (polar axis = the lateral axis; V turns the measuring plane about
 *    it, H is the angle within the plane toward the pole):
 *    H = asin(l), V = atan2(u, a); directions with |V| > 90° are behind the
 *    luminaire and get 0. Inverse: γ = acos(cos H cos V), C = atan2(cos H sin V, sin H).
 *  - Type A (polar axis = the up axis; H turns the plane about it, V is the
 *    angle within the plane toward the pole):
 *    V = asin(u), H = atan2(l, a); |H| > 90° → 0. Inverse: γ = acos(cos V cos H),
 *    C = atan2(sin V, cos V sin H).
 * (LM-63-2002 §5.15–5.17; IES LM-75 goniophotometer types; see docs/photometry.md.)
 *
 * Symmetric ranges (LM-63-2002: "the first horizontal angle will be 0 … when
 * the luminaire is laterally symmetric", vertical first angle 0 likewise) are
 * mirrored: I(−H, V) = I(H, V) and I(H, −V) = I(H, V).
 */
export function convertTypeAB(fileName: string, type: 'A' | 'B', grid: TypeCGrid, line: number | null): ExpandedGrid {
  const { verticalAngles: v, horizontalAngles: h, candela } = grid;
  const hMirror = checkRange(fileName, 'horizontal', h, line);
  const vMirror = checkRange(fileName, 'vertical', v, line);

  // Bilinear lookup in the file's (H, V) grid, mirrored where the file is symmetric.
  const lookup = (hDeg: number, vDeg: number): number => {
    const hh = hMirror ? Math.abs(hDeg) : hDeg;
    const vv = vMirror ? Math.abs(vDeg) : vDeg;
    if (hh < h[0] - EPS || hh > h[h.length - 1] + EPS || vv < v[0] - EPS || vv > v[v.length - 1] + EPS) return 0;
    const [i0, i1, s] = bracket(h, hh);
    const [j0, j1, t] = bracket(v, vv);
    const a = candela[i0][j0] * (1 - t) + candela[i0][j1] * t;
    const b = candela[i1][j0] * (1 - t) + candela[i1][j1] * t;
    return a * (1 - s) + b * s;
  };

  const nGamma = Math.round(180 / TYPE_AB_GAMMA_STEP) + 1;
  const nC = Math.round(360 / TYPE_AB_C_STEP) + 1;
  const verticalAngles = Array.from({ length: nGamma }, (_, i) => i * TYPE_AB_GAMMA_STEP);
  const horizontalAngles = Array.from({ length: nC }, (_, i) => i * TYPE_AB_C_STEP);
  const out = horizontalAngles.map((cDeg) =>
    verticalAngles.map((gDeg) => {
      const g = gDeg * DEG;
      const c = cDeg * DEG;
      const a = Math.cos(g);
      const l = Math.sin(g) * Math.cos(c);
      const u = Math.sin(g) * Math.sin(c);
      if (type === 'B') {
        const vDeg = Math.atan2(u, a) / DEG;
        if (Math.abs(vDeg) > 90 + EPS) return 0;
        return lookup(Math.asin(clamp1(l)) / DEG, vDeg);
      }
      const hDeg = Math.atan2(l, a) / DEG;
      if (Math.abs(hDeg) > 90 + EPS) return 0;
      return lookup(hDeg, Math.asin(clamp1(u)) / DEG);
    }),
  );

  // C = 360 is the C = 0 plane; copy it so the seam is exact, not just close.
  out[nC - 1] = out[0].slice();

  const symmetry: Photometry['symmetry'] = hMirror && vMirror ? 'quadrant' : hMirror ? 'bilateral-c90' : vMirror ? 'bilateral-c0' : 'none';
  return { verticalAngles, horizontalAngles, candela: out, symmetry };
}

/** Type A/B angle lists run −90..90, or 0..90 for a mirrored half. Returns true for a half. */
function checkRange(fileName: string, which: string, angles: number[], line: number | null): boolean {
  const first = angles[0];
  const last = angles[angles.length - 1];
  if (angles.length >= 2 && Math.abs(last - 90) <= EPS && (Math.abs(first + 90) <= EPS || Math.abs(first) <= EPS)) {
    return Math.abs(first) <= EPS;
  }
  throw new PhotometryParseError(fileName, line, `unsupported type A/B ${which} angle range ${first}..${last} (expected -90..90 or 0..90)`);
}

const clamp1 = (x: number): number => Math.max(-1, Math.min(1, x));

/** Indices i0 ≤ i1 around x in an ascending list and the weight of i1. */
export function bracket(angles: readonly number[], x: number): [number, number, number] {
  const n = angles.length;
  if (n === 1 || x <= angles[0]) return [0, 0, 0];
  if (x >= angles[n - 1]) return [n - 1, n - 1, 0];
  let lo = 0;
  let hi = n - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (angles[mid] <= x) lo = mid;
    else hi = mid;
  }
  return [lo, hi, (x - angles[lo]) / (angles[hi] - angles[lo])];
}
