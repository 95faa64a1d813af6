import { SURFACE_NAMES, type LightingLuminaire, type NearField, type Rgb, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import type { Photometry } from '../../core/photometry/types';
import type { MeshPlacement } from '../../core/mesh/placeMesh';
import type { TriangleMesh } from '../../core/mesh/triangleMesh';
import type { Room as ShapedRoom } from '../../core/room/normaliseRoom';
import type { BakeDaylight } from './daylight/bakeDaylight';

/**
 * One luminaire with its photometry already parsed (the baker reads no files):
 * a lighting-scene luminaire (position, yaw/pitch/roll, dimming, colour) whose
 * `photometry` is the parsed model instead of a path.
 */
export type BakeLuminaire = Omit<LightingLuminaire, 'photometry' | 'id'> & { photometry: Photometry };

/**
 * What the baker needs: the room and its luminaires. A reflectance is grey or
 * linear RGB in [0, 1). Bake a subset of luminaires (one group) to get that
 * group's basis maps: light is linear, so maps of groups add (combineMaps).
 */
export interface BakeScene {
  room: {
    width: number;
    height: number;
    depth: number;
    reflectance: Record<SurfaceName, number | Rgb>;
    /**
     * A room of any shape (issue 29; the lighting scene's `room.shape`), in world coordinates:
     * the baker bakes it inside an enclosing box of sinks (shapedRoom/encloseShapedRoom.ts,
     * docs/baker.md "Rooms of any shape"). Absent: the box [0, width] × [0, height] × [0, depth].
     */
    shape?: ShapedRoom;
    /** Set by encloseShapedRoom on the box it bakes a shaped room in (never by a caller): see RoomEnclosure. */
    enclosure?: RoomEnclosure;
  };
  luminaires: BakeLuminaire[];
  /**
   * Objects in the room (scene file v2 `objects`, the configurator's furniture): they occlude
   * direct light, are hit by the gather and get light maps of their own. Absent or empty: the
   * baker compiles exactly the shaders of an empty room.
   */
  objects?: BakeObject[];
  /**
   * Daylight through the windows of a shaped room (issue 30, docs/daylight.md "The baker"); ignored
   * for a box room without `shape` and for a room without windows, which bake exactly as before.
   */
  daylight?: BakeDaylight;
  /** Near-field model of the luminaires (scene file v2 `nearField`; absent = 'split'); the bake setting `nearField` overrides it. */
  nearField?: NearField;
}

/**
 * How a shaped room sits in the box it is baked in: bake coordinates = world + `offset`; the
 * first `surfaces.length` objects of the enclosed scene are the room's surfaces, in this order;
 * the box's six surfaces are black sinks of one texel each.
 */
export interface RoomEnclosure {
  offset: Vec3;
  shape: ShapedRoom;
  /** The room's surface ids ('floor', 'ceiling', 'slope-<i>', 'wall-<i>'), as src/core/room/roomSurfaces.ts names them; object id = ROOM_OBJECT_PREFIX + id. */
  surfaces: string[];
}

/** One object with its mesh already loaded; `reflectance` (grey or RGB) overrides every material of the mesh. */
export interface BakeObject extends MeshPlacement {
  id: string;
  mesh: TriangleMesh;
  reflectance?: number | Rgb;
}

export function toRgb(value: number | Rgb): Rgb {
  return typeof value === 'number' ? [value, value, value] : [value[0], value[1], value[2]];
}

/** Every surface's reflectance as linear RGB (what the viewer's shaders take). */
export function reflectanceRgb(room: BakeScene['room']): Record<SurfaceName, Rgb> {
  return Object.fromEntries(SURFACE_NAMES.map((n) => [n, toRgb(room.reflectance[n])])) as Record<SurfaceName, Rgb>;
}
