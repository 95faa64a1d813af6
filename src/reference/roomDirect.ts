import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import type { ReferencePointSource } from './pointSources';
import { nearestSourceGap, visibleDirectAt } from './visibleDirectAt';
import { patchPieces, type RoomPatch } from './roomPatches';
import { sightClear, type RoomSightlines } from './roomSightlines';

/**
 * Direct illuminance (lux, RGB) at point q with unit normal n in a room of any shape:
 * E = Σ I(γ, C)·cos θ / d² × V (CIE 171:2006 §5.2), V = 0 when the room itself stands between
 * q and the source (the inner corner of an L), exactly. Each source's term is the box
 * reference's directIlluminanceAt.
 */
export function roomDirectAt(sources: readonly ReferencePointSource[], sight: RoomSightlines, q: Vec3, n: Vec3, out: Rgb = [0, 0, 0]): Rgb {
  return visibleDirectAt(sources, q, n, (source) => sightClear(sight, q, n, source, null), out);
}

/** Sub-pieces per side for a patch's mean: ~8 per patch diameter over the distance to the nearest source, within [4, 16]. */
function piecesPerSide(patch: RoomPatch, sources: readonly ReferencePointSource[]): number {
  const near = nearestSourceGap(patch, sources);
  return Math.min(16, Math.max(4, Math.ceil((8 * patch.diameter) / near)));
}

/**
 * Mean direct illuminance over a patch (lux, RGB): the area-weighted midpoint rule on its
 * pieces (the patch cut by an m × m lattice, m from piecesPerSide). Shadow edges make the
 * integrand discontinuous, so a plain rule on many pieces is the robust choice; the means feed
 * only the interreflection (query points get exact values).
 */
export function patchMeanRoomDirect(sources: readonly ReferencePointSource[], sight: RoomSightlines, patch: RoomPatch): Rgb {
  const acc: Rgb = [0, 0, 0];
  if (sources.length === 0) return acc;
  const e: Rgb = [0, 0, 0];
  for (const piece of patchPieces(patch, piecesPerSide(patch, sources))) {
    roomDirectAt(sources, sight, piece.centroid, patch.normal, e);
    const w = piece.area / patch.area;
    acc[0] += w * e[0];
    acc[1] += w * e[1];
    acc[2] += w * e[2];
  }
  return acc;
}
