/**
 * A daylight bake (issue 30) against the independent daylight reference
 * (src/reference/solveDaylightReference.ts) at the G-buffer point of fully covered atlas texels of
 * the room's surfaces, with the shaped rooms' rule: points within EDGE_BAND of a surface's or an
 * opening's edge are left out and counted. Used by the tests and `npm run bench`.
 */
import type { BakeScene } from '../../engines/bake/bakeScene';
import type { BakedMaps } from '../../engines/bake/bakedMaps';
import { daylightIlluminanceAt, type DaylightReferenceResult } from '../../reference/solveDaylightReference';
import { compareAtlasWith, type ShapedComparison } from './shapedRoomComparison';

/** Every `stride`-th fully covered texel of the room's surfaces: the bake's direct and total daylight against the reference's at the texel's point. */
export function compareDaylightWithReference(scene: BakeScene, maps: BakedMaps, reference: DaylightReferenceResult, stride: number): ShapedComparison {
  return compareAtlasWith(scene, maps, stride, (surface, p) => daylightIlluminanceAt(reference, p, [surface.inward[0], surface.inward[1], surface.inward[2]]));
}
