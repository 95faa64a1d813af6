import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import { directIlluminanceAt } from './directIlluminance';
import type { ReferencePointSource } from './pointSources';

/**
 * Direct illuminance (lux, RGB) at point q with unit normal n: E = Σ I(γ, C)·cos θ / d² × V
 * (CIE 171:2006 §5.2), each source's term from the box reference's directIlluminanceAt and its
 * visibility V ∈ {0, 1} from `visible` (asked only for sources that light q at all). The furnished
 * room (objects in the way) and the room of any shape (its own walls in the way) differ only in V.
 */
export function visibleDirectAt(sources: readonly ReferencePointSource[], q: Vec3, n: Vec3, visible: (source: Vec3) => boolean, out: Rgb): Rgb {
  out[0] = 0;
  out[1] = 0;
  out[2] = 0;
  if (sources.length === 0) return out;
  const one: ReferencePointSource[] = [sources[0]];
  const e: Rgb = [0, 0, 0];
  for (const s of sources) {
    one[0] = s;
    directIlluminanceAt(one, q, n, e);
    if (!(e[0] > 0 || e[1] > 0 || e[2] > 0)) continue;
    if (!visible(s.position)) continue;
    out[0] += e[0];
    out[1] += e[1];
    out[2] += e[2];
  }
  return out;
}

/** Distance from a patch's edge (centroid less half its diameter, at least 1 mm) to the nearest source: how finely its mean must be sampled. */
export function nearestSourceGap(patch: { readonly centroid: Vec3; readonly diameter: number }, sources: readonly ReferencePointSource[]): number {
  let near = Infinity;
  for (const s of sources) {
    const d = Math.hypot(s.position[0] - patch.centroid[0], s.position[1] - patch.centroid[1], s.position[2] - patch.centroid[2]);
    near = Math.min(near, Math.max(d - 0.5 * patch.diameter, 1e-3));
  }
  return near;
}
