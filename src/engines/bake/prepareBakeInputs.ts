import { SURFACE_NAMES, type Rgb, type SurfaceName, type Vec3 } from '../../core/model/lightingScene/lightingScene';
import { InputError } from '../../core/inputError';
import { OBJECT_ROOM_TOLERANCE } from '../../core/model/lightingScene/parseLightingScene';
import { toRgb, type BakeScene } from './bakeScene';
import type { BakeSettings } from './bakeSettings';
import { createDataTexture } from './createDataTexture';
import { prepareLamps, type PreparedLamps } from './prepareLamps';
import { DATA_TEXTURE_WIDTH } from './profileTable';
import { surfaceLayouts, type SurfaceLayout } from './surfaceLayout';
import { uploadObjectPassInputs, type ObjectPassInputs } from './objects/objectPassInputs';
import { prepareObjectsCached } from './objects/prepareObjectsCached';
import type { PreparedObjects } from './objects/preparedObjects';

/** Everything a bake knows before it draws: the room's surfaces, its lamps and its objects, uploaded. */
export interface BakeInputs {
  roomSize: Vec3;
  /** A shaped room's enclosure (shapedRoom/encloseShapedRoom.ts): the six box surfaces are black one-texel sinks and get no direct pass. */
  sinks: boolean;
  /** Per surface index. */
  reflectance: Rgb[];
  layouts: SurfaceLayout[];
  lamps: PreparedLamps;
  /** The profile table as a data texture (null when no lamp emits). */
  profiles: WebGLTexture | null;
  /** The scene's objects (null: none, or an empty list — exactly the empty room). */
  objects: { prepared: PreparedObjects; inputs: ObjectPassInputs } | null;
  dispose(): void;
}

/**
 * Step 1 of a bake (startBakeJob.ts): the surface layouts for the settings, the lamps (one profile
 * table) and the objects (atlas and BVH, docs/baker.md "Objects: passes"), checked and uploaded.
 * Given direct maps (startFromDirect) with objects must come with the atlas's direct map, of the
 * atlas's size.
 */
export function prepareBakeInputs(gl: WebGL2RenderingContext, scene: BakeScene, settings: BakeSettings, directOverride: Record<SurfaceName, Float32Array> | null, objectDirectOverride: Float32Array | null): BakeInputs {
  const { room } = scene;
  const reflectance = SURFACE_NAMES.map((n) => toRgb(room.reflectance[n]));
  const layouts = surfaceLayouts(room, settings.texelSize, settings.maxTextureSize);
  const lamps = prepareLamps(scene, settings);
  const prepared = scene.objects && scene.objects.length > 0 ? prepareSceneObjects(scene, settings) : null;
  if (directOverride && prepared) checkGivenAtlasMap(prepared, objectDirectOverride);
  const profiles = lamps.table.layouts.length > 0 ? createDataTexture(gl, lamps.table.data, DATA_TEXTURE_WIDTH, lamps.table.rows) : null;
  const objects = prepared ? { prepared, inputs: uploadObjectPassInputs(gl, prepared) } : null;
  return {
    roomSize: [room.width, room.height, room.depth],
    sinks: room.enclosure !== undefined,
    reflectance,
    layouts,
    lamps,
    profiles,
    objects,
    dispose() {
      objects?.inputs.dispose();
      if (profiles) gl.deleteTexture(profiles);
    },
  };
}

function checkGivenAtlasMap(prepared: PreparedObjects, given: Float32Array | null): void {
  const expected = prepared.atlas.width * prepared.atlas.height * 3;
  if (!given) throw new Error('startFromDirect: the scene has objects but no direct map of their atlas was given');
  if (given.length !== expected) {
    throw new Error(`startFromDirect: the objects' direct map has ${given.length / 3} texels, their atlas ${prepared.atlas.width}×${prepared.atlas.height}`);
  }
}

/**
 * The scene's objects prepared for the GPU (objects/prepareObjects.ts): the atlas at the bake's
 * texel size (at most maxTextureSize per edge), after checking that every object lies inside the
 * room (OBJECT_ROOM_TOLERANCE, the scene file's 1 cm: a mesh exported a few mm below its floor
 * still bakes, with finite values): the passes trace rays only inside the box.
 */
function prepareSceneObjects(scene: BakeScene, settings: BakeSettings): PreparedObjects {
  const prepared = prepareObjectsCached(scene.objects ?? [], { texelSize: settings.texelSize, maxAtlasSize: settings.maxTextureSize });
  const size = [scene.room.width, scene.room.height, scene.room.depth];
  prepared.objects.forEach((o, k) => {
    const inside = [0, 1, 2].every((a) => o.bounds.min[a] >= -OBJECT_ROOM_TOLERANCE && o.bounds.max[a] <= size[a] + OBJECT_ROOM_TOLERANCE);
    if (!inside) {
      const fmt = (v: readonly number[]) => `(${v.map((x) => x.toFixed(3)).join(', ')})`;
      throw new InputError(`object ${k + 1} ("${o.id}") reaches outside the room: its bounds ${fmt(o.bounds.min)}–${fmt(o.bounds.max)} m, the room 0–${fmt(size)} m`);
    }
  });
  return prepared;
}
