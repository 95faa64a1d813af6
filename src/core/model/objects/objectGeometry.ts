/**
 * Objects in the room as geometry: which mesh an object shows, where its placement puts it
 * (floor or wall → position, yaw, scale for placeMesh), the world bounds of its placed
 * vertices, and the mesh with the object's finishes applied. validate() (objectProblems.ts),
 * the actions, the lighting scene and the plan outline all go through these.
 */
import { placedPositions, type MeshPlacement } from '../../mesh/placeMesh';
import { positionBounds, type Bounds3, type MeshMaterial, type TriangleMesh } from '../../mesh/triangleMesh';
import { InputError } from '../../inputError';
import type { Configuration, ObjectFinish, ObjectSource, Room, RoomObject, WallName } from '../configuration/configuration';
import { findFurnitureItem, furnitureMesh } from './furniture/furnitureLibrary';
import { objectFinishRgb } from './furniture/objectFinishes';
import type { Rgb, Vec3 } from '../lightingScene/lightingScene';

/** The mesh an object's source names, or null when the library item or imported mesh does not exist. */
export function sourceMesh(config: Configuration, source: ObjectSource): TriangleMesh | null {
  if (source.kind === 'library') return findFurnitureItem(source.item) ? furnitureMesh(source.item) : null;
  return Object.prototype.hasOwnProperty.call(config.importedMeshes, source.mesh) ? config.importedMeshes[source.mesh].mesh : null;
}

/** What the user calls the object's model: the library item's name or the imported file's name. */
export function sourceName(config: Configuration, source: ObjectSource): string {
  if (source.kind === 'library') return findFurnitureItem(source.item)?.name ?? source.item;
  return config.importedMeshes[source.mesh]?.name ?? source.mesh;
}

/**
 * Where a wall placement puts the mesh origin and which way the mesh's front (local +z) faces:
 * into the room, perpendicular to the wall. u runs along the wall as in the wall map
 * coordinates of docs/scene-format.md (north/south u = x, west/east u = z). With
 * world = T·Ry(yaw)·S·local, local +z turns to (sin yaw, cos yaw) in (x, z): yaw 0 faces +z
 * (off the north wall), 180 −z (south), 90 +x (west), 270 −x (east).
 */
export function wallFrame(wall: WallName, u: number, y: number, room: Pick<Room, 'width' | 'depth'>): { position: Vec3; yaw: number } {
  switch (wall) {
    case 'north':
      return { position: [u, y, 0], yaw: 0 };
    case 'south':
      return { position: [u, y, room.depth], yaw: 180 };
    case 'west':
      return { position: [0, y, u], yaw: 90 };
    case 'east':
      return { position: [room.width, y, u], yaw: 270 };
  }
}

/** The object's placement for placeMesh: world = T(position)·Ry(yaw)·S(scale)·local. */
export function objectPlacement(object: RoomObject, room: Pick<Room, 'width' | 'depth'>): MeshPlacement {
  const p = object.placement;
  if (p.on === 'floor') return { position: [p.x, 0, p.z], yaw: object.yaw, scale: object.scale };
  const { position, yaw } = wallFrame(p.wall, p.u, p.y, room);
  return { position, yaw, scale: object.scale };
}

interface CachedBounds {
  readonly mesh: TriangleMesh;
  readonly width: number;
  readonly depth: number;
  readonly bounds: Bounds3;
}

/** Placed bounds per object (objects are immutable); recomputed if the mesh or the room's plan size differ. */
const boundsCache = new WeakMap<RoomObject, CachedBounds>();

/** Axis-aligned world bounds of the object's placed vertices (the real rotated, scaled mesh). */
export function placedBounds(object: RoomObject, mesh: TriangleMesh, room: Pick<Room, 'width' | 'depth'>): Bounds3 {
  const hit = boundsCache.get(object);
  if (hit && hit.mesh === mesh && hit.width === room.width && hit.depth === room.depth) return hit.bounds;
  const bounds = positionBounds(placedPositions(mesh, objectPlacement(object, room)));
  boundsCache.set(object, { mesh, width: room.width, depth: room.depth, bounds });
  return bounds;
}

/** Allowed distance past a wall, floor or ceiling: Float32 vertices round at about 0.1 µm per metre. */
export const OBJECT_EPS = 1e-6;

/**
 * The placement moved the least so the placed mesh lies inside the room (its bounds are those of
 * the placed vertices, so a translation by the overshoot is exact): a free spot near the one
 * asked for. Throws InputError when the object cannot fit at any position (wider, deeper or
 * taller than the room or its wall).
 */
export function fitPlacement(object: RoomObject, mesh: TriangleMesh, room: Room, label: string): RoomObject {
  const b = placedBounds(object, mesh, room);
  // A placement near the double range gives non-finite vertices, which no shift can bring inside (issue 32).
  if (![...b.min, ...b.max].every(Number.isFinite)) throw new InputError(`object ${object.id} has a non-finite position or an unknown wall`, { code: 'objectPosition', params: { id: object.id } });
  // The object as parameters (docs/i18n.md): a UI names library furniture by its id in its own language.
  const named = { name: label, ...(object.source.kind === 'library' ? { furnitureId: object.source.item } : {}) };
  const shift = (lo: number, hi: number, max: number, what: 'along x' | 'along z' | 'high'): number => {
    const key = what === 'along x' ? 'objectTooWide' : what === 'along z' ? 'objectTooDeep' : 'objectTooHigh';
    if (hi - lo > max + OBJECT_EPS) throw new InputError(`the ${label} (${fmt(hi - lo)} m ${what}) does not fit in this ${fmt(max)} m room`, { code: key, params: { ...named, size: Number(fmt(hi - lo)), room: Number(fmt(max)) } });
    return lo < 0 ? -lo : hi > max ? max - hi : 0;
  };
  const dx = shift(b.min[0], b.max[0], room.width, 'along x');
  const dz = shift(b.min[2], b.max[2], room.depth, 'along z');
  const dy = shift(b.min[1], b.max[1], room.height, 'high');
  const p = object.placement;
  if (p.on === 'floor') {
    if (dy !== 0)
      throw new InputError(`the ${label} does not fit between floor and ceiling (${fmt(b.min[1])} … ${fmt(b.max[1])} m; room height ${fmt(room.height)} m)`, {
        code: 'objectNotBetweenFloorAndCeiling',
        params: { ...named, bottom: Number(fmt(b.min[1])), top: Number(fmt(b.max[1])), height: Number(fmt(room.height)) },
      });
    return { ...object, placement: { on: 'floor', x: p.x + dx, z: p.z + dz } };
  }
  // Along the wall the shift moves u; across it (the depth into the room) nothing can help.
  const along = p.wall === 'north' || p.wall === 'south' ? dx : dz;
  const across = p.wall === 'north' || p.wall === 'south' ? dz : dx;
  if (Math.abs(across) > OBJECT_EPS) throw new InputError(`the ${label} reaches across the room from the ${p.wall} wall`, { code: 'objectAcrossRoom', params: { ...named, wall: p.wall } });
  return { ...object, placement: { on: 'wall', wall: p.wall, u: p.u + along, y: p.y + dy } };
}

/** A finish's linear RGB: an object finish id (furniture/objectFinishes.ts) or RGB itself. */
export function finishRgb(finish: ObjectFinish): Rgb {
  return typeof finish === 'string' ? objectFinishRgb(finish) : [finish[0], finish[1], finish[2]];
}

/**
 * The object's mesh with its finishes applied (object-local; the lighting scene's object entry
 * places it). Shares the vertex and index arrays with the source mesh; only the materials differ.
 */
export function objectMesh(config: Configuration, objectId: string): TriangleMesh {
  const object = config.objects.find((o) => o.id === objectId);
  if (!object) throw new InputError(`no object with id '${objectId}'`, { code: 'unknownObject', params: { id: objectId } });
  const mesh = sourceMesh(config, object.source);
  if (!mesh) throw new InputError(`object ${objectId}: its ${object.source.kind === 'library' ? `library item '${object.source.item}'` : `imported mesh '${object.source.mesh}'`} does not exist`);
  if (Object.keys(object.finishes).length === 0) return mesh;
  const materials: MeshMaterial[] = mesh.materials.map((m) => {
    const f = Object.prototype.hasOwnProperty.call(object.finishes, m.name) ? object.finishes[m.name] : undefined;
    return f === undefined ? m : { name: m.name, reflectance: finishRgb(f) };
  });
  return { ...mesh, materials };
}

export function fmt(x: number): string {
  return String(Math.round(x * 1000) / 1000);
}
