import type { Photometry } from '../../core/photometry/types';
import { num } from './radianceFrame';

/**
 * Radiance's luminous efficacy of "white" light, lm/W (Radiance's WHTEFFICACY, `ies2rad.c`):
 * candela become W/sr by dividing by it, and `rtrace -I` irradiance becomes lux by multiplying.
 */
export const WHITE_EFFICACY = 179;

/** Which part of the distribution a point source emits (scenePointSources: the faces of a tall opening). */
export type EmittingSide = -1 | 0 | 1;

/**
 * The candela distribution as a Radiance `brightdata` data file, in the layout `ies2rad`
 * writes (`cvdata` in Radiance's src/cv/ies2rad.c): the number of dimensions, then per
 * dimension "first last count" for evenly spaced angles or "0 0 count" and the list, horizontal
 * (φ = C) before vertical (θ = γ), then the values in W/sr (cd / 179), four to a line, vertical
 * angles running fastest. luxbox's grid is already expanded (symmetry unfolded, multipliers
 * applied, C spanning 0..360 or a single plane), so the file is addressed by source.cal's
 * `src_phi src_theta` (or `src_theta` alone for a rotationally symmetric lamp).
 *
 * `side` keeps only the lower (−1: γ ≤ 90°) or upper (+1: γ ≥ 90°) hemisphere, for the point
 * sources on the bottom and top faces of a tall luminous opening.
 */
export function brightdataFile(photometry: Photometry, side: EmittingSide = 0): string {
  const { verticalAngles: v, horizontalAngles: h, candela } = photometry;
  const dims = h.length > 1 ? [h, v] : [v];
  const lines: string[] = [String(dims.length)];
  for (const angles of dims) lines.push(angleLine(angles));
  const values: string[] = [];
  for (let i = 0; i < h.length; i++) {
    for (let j = 0; j < v.length; j++) {
      const outside = (side < 0 && v[j] > 90) || (side > 0 && v[j] < 90);
      const cd = outside ? 0 : candela[i][j];
      values.push(num(Math.max(0, cd) / WHITE_EFFICACY));
    }
  }
  for (let k = 0; k < values.length; k += 4) lines.push('\t' + values.slice(k, k + 4).join('\t'));
  return lines.join('\n') + '\n';
}

function angleLine(angles: readonly number[]): string {
  const step = angles[1] - angles[0];
  const even = angles.every((a, i) => i === 0 || Math.abs(a - angles[i - 1] - step) < 1e-6);
  if (even) return `${num(angles[0])} ${num(angles[angles.length - 1])} ${angles.length}`;
  const rows: string[] = [`0 0 ${angles.length}`];
  for (let k = 0; k < angles.length; k += 4)
    rows.push(
      '\t' +
        angles
          .slice(k, k + 4)
          .map(num)
          .join('\t'),
    );
  return rows.join('\n');
}
