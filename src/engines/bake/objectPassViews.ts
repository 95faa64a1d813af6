import type { ObjectGatherSamplers } from './createBounceIteration';
import type { FluxObjects } from './fluxStatistics';
import type { PlanObjects } from './planBakePasses';
import type { BrightPatchObjects } from './runBrightPatchPass';
import type { BakeInputs } from './prepareBakeInputs';
import { chartTileFrames } from './tileFrame';

/** The scene's objects as each pass takes them (all null for the empty room). */
export interface ObjectPassViews {
  plan: PlanObjects | null;
  /** The BVH samplers of the direct passes (empty without objects). */
  directSamplers: { uBvhNodes?: WebGLTexture; uBvhTriangles?: WebGLTexture };
  flux: FluxObjects | null;
  bright: BrightPatchObjects | null;
  gather: ObjectGatherSamplers | null;
}

/**
 * One place that says which of the objects' textures and sizes each pass reads (docs/baker.md,
 * "Objects: passes"). The bright-patch search takes candidates on the atlas's charts as well as on
 * the room's surfaces: a shaped room's surfaces are charts (docs/baker.md "Rooms of any shape"),
 * and in a furnished box room the brightest patches are often on furniture (a spot's pool on a
 * table top), whose first bounce the Monte Carlo gather alone finds too rarely (docs/baker.md
 * "Noise of the indirect light").
 */
export function objectPassViews(objects: BakeInputs['objects']): ObjectPassViews {
  if (!objects) return { plan: null, directSamplers: {}, flux: null, bright: null, gather: null };
  const { prepared, inputs } = objects;
  const { atlas } = prepared;
  const bvh = { uBvhNodes: inputs.bvhNodes, uBvhTriangles: inputs.bvhTriangles };
  return {
    plan: { bvhWidth: prepared.bvh.width, atlasWidth: atlas.width, atlasHeight: atlas.height, maxReflectance: inputs.maxReflectance },
    directSamplers: bvh,
    flux: {
      width: atlas.width,
      height: atlas.height,
      texelSize: atlas.texelSize,
      points: inputs.points,
      reflectance: inputs.reflectance,
      maxReflectance: inputs.maxReflectance,
    },
    bright: {
      bvhWidth: prepared.bvh.width,
      atlasWidth: atlas.width,
      atlasHeight: atlas.height,
      ...bvh,
      uPoints: inputs.points,
      uNormals: inputs.normals,
      charts: { frames: chartTileFrames(prepared), reflectance: inputs.reflectance, texelSize: atlas.texelSize },
    },
    gather: { uObjectRho: inputs.reflectance, ...bvh, uPoints: inputs.points, uNormals: inputs.normals },
  };
}
