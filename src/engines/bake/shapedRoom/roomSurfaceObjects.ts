/**
 * A shaped room's surfaces as the baker's objects (issue 29): each planar surface of the room
 * (src/core/room/roomSurfaces.ts: floor, flat ceiling part, slope parts, wall polygons with their
 * openings left out) becomes one BakeObject whose mesh is that surface's triangles
 * (src/core/room/roomTriangles.ts), wound counterclockwise seen from inside the room, so the lit
 * front faces the room. As objects they get planar charts in the objects' atlas (one object per
 * surface: no chart and no blur crosses from one surface to another), texels outside the
 * polygon or inside an opening have no coverage, and they occlude through the objects' BVH.
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { Room } from '../../../core/room/normaliseRoom';
import { roomTriangles } from '../../../core/room/roomTriangles';
import type { BakeObject } from '../bakeScene';

/** Object ids of the room's surfaces: this prefix and the surface id ('room:floor', 'room:wall-2', …). */
export const ROOM_OBJECT_PREFIX = 'room:';

/** Highest reflectance a surface bakes with (collectWorldTriangles clamps objects to [0, 0.999] too). */
const MAX_REFLECTANCE = 0.999;

/** The room's surfaces as objects, translated by `offset` (world → bake coordinates), in roomSurfaces order; surfaces without triangles are left out. */
export function roomSurfaceObjects(room: Room, offset: Vec3): { objects: BakeObject[]; surfaces: string[] } {
  const { surfaces, positions, surfaceOf } = roomTriangles(room);
  const objects: BakeObject[] = [];
  const ids: string[] = [];
  surfaces.forEach((surface, k) => {
    const triangles: number[] = [];
    surfaceOf.forEach((s, t) => {
      if (s === k) triangles.push(t);
    });
    if (triangles.length === 0) return;
    const meshPositions = new Float32Array(triangles.length * 9);
    triangles.forEach((t, m) => {
      for (let c = 0; c < 9; c++) meshPositions[9 * m + c] = positions[9 * t + c];
    });
    const reflectance = surface.reflectance.map((r) => Math.min(MAX_REFLECTANCE, Math.max(0, r))) as [number, number, number];
    objects.push({
      id: ROOM_OBJECT_PREFIX + surface.id,
      mesh: {
        positions: meshPositions,
        indices: Uint32Array.from({ length: triangles.length * 3 }, (_, i) => i),
        materialOfTriangle: new Uint16Array(triangles.length),
        materials: [{ name: surface.id, reflectance }],
      },
      position: [offset[0], offset[1], offset[2]],
      yaw: 0,
      scale: 1,
      reflectance,
    });
    ids.push(surface.id);
  });
  return { objects, surfaces: ids };
}
