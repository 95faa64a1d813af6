import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import { subdivideTriangle, type FurnishedPatch } from './furnishedPatches';
import { segmentClear, type Occluders } from './occluders';
import type { ReferencePointSource } from './pointSources';
import { nearestSourceGap, visibleDirectAt } from './visibleDirectAt';

/**
 * Direct illuminance (lux, RGB) at point q with unit normal n in a furnished room:
 * E = Σ I(γ, C)·cos θ / d² × V, with V = 1 when the segment from q to the source
 * misses every object triangle, else 0 (CIE 171:2006 §5.2 with an opaque obstruction).
 * Each source's unoccluded term comes from the box reference's directIlluminanceAt.
 */
export function occludedDirectAt(sources: readonly ReferencePointSource[], occ: Occluders | null, q: Vec3, n: Vec3, out: Rgb = [0, 0, 0]): Rgb {
  return visibleDirectAt(sources, q, n, (source) => !occ || segmentClear(occ, q, n, source, null), out);
}

/** Cells per side of a patch for its mean direct light: ~3 per patch diameter over the distance to the nearest source, within [2, 12]. */
function cellsFor(patch: FurnishedPatch, sources: readonly ReferencePointSource[]): number {
  const near = nearestSourceGap(patch, sources);
  return Math.min(12, Math.max(2, Math.ceil((3 * patch.diameter) / near)));
}

/**
 * Mean direct illuminance over a patch (lux, RGB) by the midpoint rule on m × m equal
 * cells (rectangles) or m² similar triangles, m from cellsFor. Shadow edges make the
 * integrand discontinuous, so a plain rule with many cells is the robust choice; the
 * patch means only feed the interreflection (query points get exact point values).
 */
export function patchMeanOccludedDirect(sources: readonly ReferencePointSource[], occ: Occluders | null, patch: FurnishedPatch): Rgb {
  const acc: Rgb = [0, 0, 0];
  if (sources.length === 0) return acc;
  const m = cellsFor(patch, sources);
  const e: Rgb = [0, 0, 0];
  const add = (q: Vec3, w: number): void => {
    occludedDirectAt(sources, occ, q, patch.normal, e);
    acc[0] += w * e[0];
    acc[1] += w * e[1];
    acc[2] += w * e[2];
  };
  const v = patch.vertices;
  if (v.length === 4) {
    // Rectangle a, b, c, d: u along a→b, v along a→d.
    for (let i = 0; i < m; i++) {
      for (let j = 0; j < m; j++) {
        const s = (i + 0.5) / m;
        const t = (j + 0.5) / m;
        add([0, 1, 2].map((x) => v[0][x] + s * (v[1][x] - v[0][x]) + t * (v[3][x] - v[0][x])) as Vec3, 1 / (m * m));
      }
    }
  } else {
    for (const piece of subdivideTriangle(v[0], v[1], v[2], m)) {
      add([0, 1, 2].map((x) => (piece[0][x] + piece[1][x] + piece[2][x]) / 3) as Vec3, 1 / (m * m));
    }
  }
  return acc;
}
