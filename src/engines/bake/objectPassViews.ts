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
 * "Objects: passes"). `chartPatches`: the bright-patch search takes candidates on the atlas's
 * charts too (a shaped room, whose surfaces are charts; docs/baker.md "Rooms of any shape").
 */
export function objectPassViews(objects: BakeInputs['objects'], chartPatches = false): ObjectPassViews {
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
      charts: chartPatches ? { frames: chartTileFrames(prepared), reflectance: inputs.reflectance, texelSize: atlas.texelSize } : null,
    },
    gather: { uObjectRho: inputs.reflectance, ...bvh, uPoints: inputs.points, uNormals: inputs.normals },
  };
}
