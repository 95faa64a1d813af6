import type { Vec3 } from '../core/model/lightingScene/lightingScene';
import { frontFormFactor } from './occludedFormFactor';
import { patchPieces, type PatchPiece, type RoomPatch } from './roomPatches';
import { sightClear, type RoomSightlines } from './roomSightlines';

/** Pieces of a patch at a level (1, 4 or 16 pieces), cached per patch. */
export class PieceCache {
  private readonly levels = new Map<number, PatchPiece[][]>();
  constructor(private readonly patches: readonly RoomPatch[]) {}
  get(k: number, level: 1 | 2): PatchPiece[] {
    let list = this.levels.get(k);
    if (!list) this.levels.set(k, (list = []));
    return (list[level] ??= patchPieces(this.patches[k], level === 1 ? 2 : 4));
  }
}

/**
 * The share of emitter patch e that point x (normal n) sees, by sight lines to the centroids of
 * its 2 × 2 pieces, refined to its 4 × 4 pieces where they disagree (a shadow edge crosses it);
 * area-weighted. 1 in a convex room.
 */
export function visibleShare(sight: RoomSightlines, x: Vec3, n: Vec3, e: RoomPatch, k: number, cache: PieceCache): number {
  if (sight.convex) return 1;
  const coarse = cache.get(k, 1);
  let seen = 0;
  let any = false;
  let all = true;
  for (const p of coarse) {
    const clear = sightClear(sight, x, n, p.centroid, e.normal);
    any ||= clear;
    all &&= clear;
    if (clear) seen += p.area;
  }
  if (all) return 1;
  if (!any) return 0;
  seen = 0;
  for (const p of cache.get(k, 2)) if (sightClear(sight, x, n, p.centroid, e.normal)) seen += p.area;
  return seen / e.area;
}

/** Form factor from point x (normal n) to patch e, visible part only: Lambert's contour integral × the visible share. */
export function pointToPatch(sight: RoomSightlines, x: Vec3, n: Vec3, e: RoomPatch, k: number, cache: PieceCache): number {
  const v0 = e.vertices[0];
  // The emitter radiates from its front only.
  if (e.normal[0] * (x[0] - v0[0]) + e.normal[1] * (x[1] - v0[1]) + e.normal[2] * (x[2] - v0[2]) <= 1e-12) return 0;
  const f = frontFormFactor(x, n, e.vertices);
  return f > 0 ? f * visibleShare(sight, x, n, e, k, cache) : 0;
}
