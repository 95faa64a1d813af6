/**
 * The windows of a shaped room as the daylight pass sees them, in bake coordinates (world +
 * the enclosure's offset): a rectangle c0 + a·edgeA + b·edgeB (a, b in [0, 1]) in a vertical
 * wall, edgeA horizontal along the wall, edgeB straight up, its normal into the room, its glazing.
 * Doors and plain openings lead indoors and let no daylight in (docs/daylight.md, the contract).
 */
import { OPEN_OPENING, type Glazing } from '../../../core/daylight/glazing';
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { Room } from '../../../core/room/normaliseRoom';
import { roomSurfaces } from '../../../core/room/roomSurfaces';

export interface BakeWindow {
  opening: number;
  corner: Vec3;
  edgeA: Vec3;
  edgeB: Vec3;
  inward: Vec3;
  area: number;
  glazing: Glazing;
}

export function daylightWindows(shape: Room, offset: Vec3, glazing: ReadonlyMap<number, Glazing>): BakeWindow[] {
  const out: BakeWindow[] = [];
  for (const surface of roomSurfaces(shape)) {
    for (const o of surface.openings) {
      if (o.kind !== 'window') continue;
      // openingOnWall's corner order: (offset, sill), (offset + width, sill), (…, sill + height), (offset, sill + height).
      const [c0, c1, , c3] = o.polygon;
      const corner: Vec3 = [c0[0] + offset[0], c0[1] + offset[1], c0[2] + offset[2]];
      out.push({
        opening: o.inputIndex,
        corner,
        edgeA: [c1[0] - c0[0], c1[1] - c0[1], c1[2] - c0[2]],
        edgeB: [c3[0] - c0[0], c3[1] - c0[1], c3[2] - c0[2]],
        inward: [surface.inward[0], surface.inward[1], surface.inward[2]],
        area: o.area,
        glazing: glazing.get(o.inputIndex) ?? OPEN_OPENING,
      });
    }
  }
  return out;
}
