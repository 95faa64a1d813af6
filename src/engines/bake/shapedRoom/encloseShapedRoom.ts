/**
 * A room of any shape baked with the objects' machinery (issue 29, docs/baker.md "Rooms of any
 * shape"): the scene becomes a box scene, the **enclosure**, that holds the room with a margin
 * on every side. Its six surfaces are black (ρ = 0) sinks of one texel each: light that leaves
 * through an opening lands there and is lost, as the issue asks until daylight exists. The room's
 * own surfaces enter as objects (roomSurfaceObjects.ts), before the scene's objects, so they get
 * atlas charts, shadow the lamps and each other through the BVH and are hit by every gather.
 *
 * The margin keeps every room surface strictly inside the box: where a room surface lay in a box
 * face (every floor, every flat ceiling, an outer wall of an L) the gather's box exit and the BVH
 * hit would tie and rounding would pick the black box half the time. Bake coordinates are world
 * coordinates + `offset`, so the outline's bounding box starts at the margin whatever its
 * minimum corner.
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { Room } from '../../../core/room/normaliseRoom';
import type { BakeObject, BakeScene } from '../bakeScene';
import { roomSurfaceObjects } from './roomSurfaceObjects';

/** Gap (m) between the room and its enclosing box on every side: far above float rounding and the 0.1 mm ray offset, and small enough to cost nothing. */
export const ENCLOSURE_MARGIN = 0.05;

const BLACK = { floor: 0, ceiling: 0, north: 0, south: 0, west: 0, east: 0 };
const NO_OBJECTS: readonly BakeObject[] = [];

/** Enclosed scenes, remembered per shape and objects list, so the relight engine's groups (and the view) share one objects array and so one prepared atlas (prepareObjectsCached). */
const cache = new WeakMap<Room, WeakMap<readonly BakeObject[], { objects: BakeObject[]; offset: Vec3; size: Vec3; surfaces: string[] }>>();

/** The shape's enclosure: the offset world → bake coordinates and the box's size. */
export function enclosureBox(shape: Room): { offset: Vec3; size: Vec3 } {
  const xs = shape.corners.map((c) => c[0]);
  const zs = shape.corners.map((c) => c[1]);
  const m = ENCLOSURE_MARGIN;
  // The flat ceiling is the highest point of any ceiling (slopes only lower it: the ceiling is the lowest plane).
  return {
    offset: [m - Math.min(...xs), m, m - Math.min(...zs)],
    size: [Math.max(...xs) - Math.min(...xs) + 2 * m, shape.height + 2 * m, Math.max(...zs) - Math.min(...zs) + 2 * m],
  };
}

const shift = (p: readonly number[], o: Vec3): Vec3 => [p[0] + o[0], p[1] + o[1], p[2] + o[2]];

/**
 * The scene as the baker bakes it: unchanged without `room.shape`; with one, the enclosure (box
 * of sinks, the room's surfaces as the first objects, luminaires and objects moved into bake
 * coordinates) with `room.enclosure` saying how. Idempotent: an enclosed scene has no shape.
 */
export function encloseShapedRoom(scene: BakeScene): BakeScene {
  const shape = scene.room.shape;
  if (!shape) return scene;
  const given = scene.objects ?? NO_OBJECTS;
  let perShape = cache.get(shape);
  if (!perShape) cache.set(shape, (perShape = new WeakMap()));
  let enclosed = perShape.get(given);
  if (!enclosed) {
    const { offset, size } = enclosureBox(shape);
    const room = roomSurfaceObjects(shape, offset);
    const moved = given.map((o): BakeObject => ({ ...o, position: shift(o.position, offset) }));
    enclosed = { objects: [...room.objects, ...moved], offset, size, surfaces: room.surfaces };
    perShape.set(given, enclosed);
  }
  const { offset, size, objects, surfaces } = enclosed;
  return {
    room: { width: size[0], height: size[1], depth: size[2], reflectance: BLACK, enclosure: { offset, shape, surfaces } },
    luminaires: scene.luminaires.map((l) => ({ ...l, position: shift(l.position, offset) })),
    objects,
    ...(scene.nearField ? { nearField: scene.nearField } : {}),
  };
}
