/**
 * Shared by the shaped-room bake tests (issue 29): scenes of any shape as the baker takes them; the
 * comparison with the room reference is src/hosts/bench/shapedRoomComparison.ts (the bench uses it too).
 */
import type { LightingLuminaire } from '../../../src/core/model/lightingScene/lightingScene';
import type { Photometry } from '../../../src/core/photometry/types';
import { normaliseRoom, type Room } from '../../../src/core/room/normaliseRoom';
import type { RoomInput } from '../../../src/core/room/roomInput';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';

/** The box a shaped room's LightingRoom carries (width/depth the outline's extents), with the shape. */
export function shapedBakeRoom(input: RoomInput): BakeScene['room'] & { shape: Room } {
  const shape = normaliseRoom(input);
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const r = 0.5;
  return { width: Math.max(...xs) - Math.min(...xs), height: shape.height, depth: Math.max(...zs) - Math.min(...zs), reflectance: { floor: r, ceiling: r, north: r, south: r, west: r, east: r }, shape };
}

export function bakeLuminaires(lamps: readonly LightingLuminaire[], files: Record<string, Photometry>): BakeScene['luminaires'] {
  return lamps.map((l) => ({ ...l, photometry: files[l.photometry], dimming: l.dimming ?? 1, color: l.color ?? [1, 1, 1] }));
}

export { compareWithReference, relativeErrors, EDGE_BAND, type SurfacePoint, type ShapedComparison } from '../../../src/hosts/bench/shapedRoomComparison';
