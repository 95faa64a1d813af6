/**
 * A room of any shape in the 3D view (issue 29, docs/viewer.md "Rooms of any shape"): the baker
 * lights it inside an enclosure whose six box surfaces are black sinks and whose own surfaces are
 * the first objects of the atlas (engines/bake/shapedRoom). The view therefore never draws the six
 * box surfaces (their layouts say `sink`), draws the objects' mesh (the room's surfaces with their openings as holes, slopes,
 * furniture) moved back from bake to world coordinates, and lets a ray pass through the outside
 * of a room surface, as it passes through the box's culled walls.
 */
import type * as THREE from 'three';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import { enclosureBox } from '../bake/shapedRoom/encloseShapedRoom';
import { OBJECTS_MESH_NAME, type RoomObjects } from './createRoomObjects';

/** Show the shaped room (or, with null, the box again): objects placed in world coordinates (the box surfaces of its sink layouts are never drawn: createRoomSurfaces). */
export function applyRoomShape(objects: RoomObjects, shape: ShapedRoom | null): void {
  const offset = shape ? enclosureBox(shape).offset : [0, 0, 0];
  objects.group.position.set(-offset[0], -offset[1], -offset[2]);
  objects.group.updateMatrixWorld(true);
}

/**
 * The first hit a pick should see: hidden box surfaces are skipped (three's Raycaster does not
 * look at `visible`), and so is the outside (back) of a shaped room's surface, which the view does
 * not draw (objectSurface.glsl's uFrontOnlyBelow).
 */
export function firstSeenHit(hits: readonly THREE.Intersection[], objects: RoomObjects, ray: THREE.Ray): THREE.Intersection | undefined {
  return hits.find((h) => {
    if (!h.object.visible) return false;
    if (h.object.name !== OBJECTS_MESH_NAME || h.faceIndex == null || !h.face) return true;
    if (objects.roomSurfaceAt(h.faceIndex) === null) return true;
    return h.face.normal.dot(ray.direction) < 0;
  });
}
