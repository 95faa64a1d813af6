import { PhotometryParseError } from './PhotometryParseError';
import type { Photometry } from './types';

/** A type-C grid as stored in a file: planes[h][v] in cd, angles in degrees. */
export interface TypeCGrid {
  verticalAngles: number[];
  horizontalAngles: number[];
  candela: number[][];
}

export interface ExpandedGrid extends TypeCGrid {
  symmetry: Photometry['symmetry'];
}

const EPS = 1e-6;
/**
 * Width of the zero-intensity skirt appended just beyond a partial vertical
 * range (e.g. 0–90°). It is tiny so the measured value at the last angle is not
 * smeared into the unmeasured hemisphere (which would add flux the file does
 * not contain), yet non-zero so the grid stays strictly ascending.
 */
export const VERTICAL_PAD_DEG = 0.01;

const near = (a: number, b: number): boolean => Math.abs(a - b) <= EPS;

/**
 * How each LM-63 horizontal range is unfolded (LM-63-2002 §5.17 and the 1995
 * "90–270" variant). `fold` maps any C in [0, 360] onto the range the file
 * measured; `images` lists where a measured plane appears in the full circle.
 */
interface HorizontalRule {
  symmetry: Photometry['symmetry'];
  fold(c: number): number;
  images(a: number): number[];
}

function horizontalRule(first: number, last: number, count: number): HorizontalRule | null {
  if (count === 1) return { symmetry: 'rotational', fold: () => first, images: () => [0] };
  const toQuadrant = (c: number): number => {
    const half = c > 180 ? 360 - c : c;
    return half > 90 ? 180 - half : half;
  };
  if (near(first, 0) && near(last, 90)) {
    return { symmetry: 'quadrant', fold: toQuadrant, images: (a) => [a, 180 - a, 180 + a, 360 - a] };
  }
  if (near(first, 90) && near(last, 180)) {
    // The same quadrant symmetry, measured in the second quadrant.
    return { symmetry: 'quadrant', fold: (c) => 180 - toQuadrant(c), images: (a) => [a, 180 - a, 180 + a, 360 - a] };
  }
  if (near(first, 0) && near(last, 180)) {
    return { symmetry: 'bilateral-c0', fold: (c) => (c > 180 ? 360 - c : c), images: (a) => [a, 360 - a] };
  }
  if (near(first, 90) && near(last, 270)) {
    // Symmetric about the 90–270 plane: I(C) = I(180 − C).
    return {
      symmetry: 'bilateral-c90',
      fold: (c) => (c >= 90 && c <= 270 ? c : (((180 - c) % 360) + 360) % 360),
      images: (a) => [a, (((180 - a) % 360) + 360) % 360],
    };
  }
  if (near(first, 0) && last > 180 && last <= 360 + EPS) {
    // No symmetry. A last plane short of 360 (e.g. 345) is closed by the 0 plane.
    return { symmetry: 'none', fold: (c) => (c > last + EPS ? 0 : c), images: (a) => [a] };
  }
  return null;
}

/**
 * Unfolds a type-C grid into the form types.ts promises: horizontal angles
 * either [0] or 0..360 inclusive, vertical angles 0..180 with zero rows padded
 * just beyond a partial measured range. Non-fatal findings (a 360° plane that
 * is not the 0° plane) are pushed onto `warnings`.
 */
export function expandTypeC(fileName: string, grid: TypeCGrid, line: number | null, warnings: string[] = []): ExpandedGrid {
  const { horizontalAngles: h, candela } = grid;
  // Ends within EPS of the poles are the poles (found by fuzzing: a first
  // angle of 5e-324 was kept, so the grid did not start at exactly 0).
  const v = grid.verticalAngles.slice();
  if (v[0] <= EPS) v[0] = 0;
  if (v[v.length - 1] >= 180 - EPS) v[v.length - 1] = 180;
  const rule = horizontalRule(h[0], h[h.length - 1], h.length);
  if (!rule) {
    throw new PhotometryParseError(fileName, line, `unsupported horizontal angle range ${h[0]}..${h[h.length - 1]} (LM-63 type C allows 0, 0..90, 0..180, 0..360, 90..180 or 90..270)`);
  }
  if (rule.symmetry === 'none' && near(h[h.length - 1], 360)) {
    const warning = seamWarning(candela[0], candela[h.length - 1], v);
    if (warning) warnings.push(warning);
  }

  // Horizontal: the set of all images of the measured planes, 0 and 360 both present.
  let planes: number[];
  let rows: number[][];
  if (rule.symmetry === 'rotational') {
    planes = [0];
    rows = [candela[0].slice()];
  } else {
    const all = new Set<number>();
    for (const a of h) {
      for (const image of rule.images(a)) {
        const c = Math.round(image * 1e9) / 1e9;
        if (c >= -EPS && c <= 360 + EPS) all.add(Math.min(360, Math.max(0, c)));
      }
    }
    all.add(0);
    all.add(360);
    planes = [...all].sort((x, y) => x - y);
    // Merge angles closer than EPS created by rounding of images.
    planes = planes.filter((c, i) => i === 0 || c - planes[i - 1] > EPS);
    planes[planes.length - 1] = 360;
    rows = planes.map((c) => candela[nearestIndex(h, rule.fold(c === 360 ? 0 : c))].slice());
  }

  // Vertical: pad partial ranges with zero rows (see VERTICAL_PAD_DEG).
  const first = v[0];
  const last = v[v.length - 1];
  const before: number[] = [];
  const after: number[] = [];
  if (first > EPS) {
    before.push(0);
    if (first - VERTICAL_PAD_DEG > EPS) before.push(first - VERTICAL_PAD_DEG);
  }
  if (last < 180 - EPS) {
    if (last + VERTICAL_PAD_DEG < 180 - EPS) after.push(last + VERTICAL_PAD_DEG);
    after.push(180);
  }
  const verticalAngles = [...before, ...v, ...after];
  const zerosBefore = before.map(() => 0);
  const zerosAfter = after.map(() => 0);
  const expanded = rows.map((row) => [...zerosBefore, ...row, ...zerosAfter]);
  return { verticalAngles, horizontalAngles: planes, candela: expanded, symmetry: rule.symmetry };
}

/**
 * C = 360 is the same half-plane as C = 0, so a file's 360° plane should repeat
 * its 0° plane. The model keeps one (the 0° plane, as most readers do); when
 * the file's two differ by more than 0.1 % of their peak that choice changes
 * the light, so it is said (issue 18).
 */
function seamWarning(at0: number[], at360: number[], vertical: number[]): string | null {
  let peak = 0;
  let diff = 0;
  let where = 0;
  for (let i = 0; i < at0.length; i++) {
    peak = Math.max(peak, at0[i], at360[i]);
    const d = Math.abs(at0[i] - at360[i]);
    if (d > diff) {
      diff = d;
      where = i;
    }
  }
  if (!(diff > 1e-3 * peak)) return null;
  const pct = Number(((diff / peak) * 100).toPrecision(3));
  return `the 360° plane differs from the 0° plane (by up to ${Number(diff.toPrecision(4))} cd, ${pct} % of their peak, at γ ${vertical[where]}°); the 0° plane is used for both`;
}

/** Index of the angle in the ascending list closest to `x`. */
function nearestIndex(angles: number[], x: number): number {
  let lo = 0;
  let hi = angles.length - 1;
  while (hi - lo > 1) {
    const mid = (lo + hi) >> 1;
    if (angles[mid] <= x) lo = mid;
    else hi = mid;
  }
  return Math.abs(angles[hi] - x) < Math.abs(angles[lo] - x) ? hi : lo;
}
