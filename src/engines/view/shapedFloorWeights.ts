import type { ObjectAtlas, PreparedObjects } from '../bake/objects/preparedObjects';
import { ROOM_OBJECT_PREFIX } from '../bake/shapedRoom/roomSurfaceObjects';

/**
 * A shaped room's floor as the GPU statistics weigh it (createGpuStats.ts StatsMask): per atlas
 * texel its coverage where the texel belongs to the floor (the room's surfaces are the first
 * objects of the atlas, roomSurfaceObjects.ts), else 0; the weights roomSurfaceStats.ts gives the
 * floor's texels on the CPU, so Ē = Σ w·Y / Σ w and the min and max over the texels with w > 0 are
 * the CPU's floor statistics. Null when the atlas has no floor.
 */
export function shapedFloorWeights(prepared: PreparedObjects, atlas: ObjectAtlas = prepared.atlas): Float32Array | null {
  const floor = prepared.objects.findIndex((o) => o.id === `${ROOM_OBJECT_PREFIX}floor`);
  if (floor < 0) return null;
  const weights = new Float32Array(atlas.width * atlas.height);
  for (let t = 0; t < weights.length; t++) {
    const w = atlas.position[4 * t + 3];
    if (w > 0 && atlas.reflectance[4 * t + 3] - 1 === floor) weights[t] = w;
  }
  return weights;
}
