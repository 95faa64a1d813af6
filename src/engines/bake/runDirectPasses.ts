import type { SurfaceName } from '../../core/model/lightingScene/lightingScene';
import type { BakeJobTargets } from './bakeJobTargets';
import type { CompilePass } from './createPassCompiler';
import { clearTarget, uploadRgb } from './floatTarget';
import type { ObjectPassViews } from './objectPassViews';
import type { BakePlan } from './planBakePasses';
import type { BakeInputs } from './prepareBakeInputs';
import { runPass } from './runPass';

/** Given direct maps (startFromDirect): per surface, and the atlas's with objects. */
export interface GivenDirect {
  surfaces: Record<SurfaceName, Float32Array>;
  objects: Float32Array | null;
}

/**
 * Step 4 of a bake (startBakeJob.ts): the direct maps, drawn by each surface's direct pass (with
 * objects, shadowed through the BVH) and the atlas's, or uploaded when given; a surface no
 * luminaire reaches is cleared. Returns the surfaces skipped (for the report).
 */
export function runDirectPasses(gl: WebGL2RenderingContext, compile: CompilePass, plan: BakePlan, inputs: BakeInputs, views: ObjectPassViews, targets: BakeJobTargets, given: GivenDirect | null): SurfaceName[] {
  const skipped: SurfaceName[] = [];
  targets.surfaces.forEach((st, s) => {
    const pass = plan.direct[s];
    // With objects the pass also takes the BVH (generateShadowedDirectShader).
    const values = { uProfiles: inputs.profiles!, ...views.directSamplers, ...pass?.lampValues };
    if (given) uploadRgb(gl, st.direct, given.surfaces[st.layout.name]);
    else if (pass) runPass(gl, compile(pass, 'direct', st.layout.name), st.direct, values);
    else {
      skipped.push(st.layout.name);
      clearTarget(gl, st.direct);
    }
  });
  const atlas = targets.atlas;
  const objects = inputs.objects?.inputs;
  if (atlas && objects) {
    if (given && given.objects) uploadRgb(gl, atlas.direct, given.objects);
    else if (plan.objectDirect) {
      runPass(gl, compile(plan.objectDirect, 'direct objects'), atlas.direct, {
        uProfiles: inputs.profiles!,
        uBvhNodes: objects.bvhNodes,
        uBvhTriangles: objects.bvhTriangles,
        uPoints: objects.points,
        uNormals: objects.normals,
        ...plan.objectDirect.lampValues,
      });
    } else clearTarget(gl, atlas.direct);
  }
  return skipped;
}
