import type { BrightPatch } from './selectBrightPatches';

/** Texels per patch in the patch table (one row per patch). */
export const PATCH_TABLE_WIDTH = 4;

/**
 * The bright patches as the bright gather reads them (shaders/brightPatchGather.glsl.ts):
 * one RGBA row per patch, (centre.xyz, surface index), (half edge along u as a
 * world vector, 0), (half edge along v, 0), (exitance M.rgb, 0).
 */
export function patchTable(patches: readonly BrightPatch[]): Float32Array {
  const data = new Float32Array(patches.length * PATCH_TABLE_WIDTH * 4);
  patches.forEach((p, k) => {
    const hu = p.axisU.map((x) => x * p.halfU);
    const hv = p.axisV.map((x) => x * p.halfV);
    data.set([...p.centre, p.surface, ...hu, 0, ...hv, 0, ...p.exitance, 0], PATCH_TABLE_WIDTH * 4 * k);
  });
  return data;
}
