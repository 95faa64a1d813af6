/** An L3D body (l3dBody.ts) as a placed module's model, with the rail hardware above it; apart from l3dBody.ts so the bake feed's chunk, which loads bodies, stays free of three.js. */
import type { Vec3 } from '../../../core/gldf/readL3dStructure';
import { aimJoints, mountFrameAxis, poseL3dBody, type BodyPlacement, type L3dBody } from './l3dBody';
import { ADAPTER, STEM_RADIUS } from './luminaireDimensions';
import type { LuminaireModel } from './luminaireModel';
import { boxPart, rodPart } from './partMesh';

/**
 * The model of a placed module with an L3D body: every part in frame 'mount' (posed here, so the
 * view's frames need no pivot), the joints aimed as the module is, and, when it hangs in a rail
 * above the body's top, a stem up to an adapter in the profile (as the generic models have).
 */
export function l3dLuminaireModel(body: L3dBody, p: BodyPlacement): { model: LuminaireModel; angles: Map<string, Vec3> } {
  const angles = aimJoints(body, mountFrameAxis(p), p.orientation.yaw - p.heading);
  const parts = poseL3dBody(body, angles).parts;
  if (p.mount > 0) {
    parts.push(boxPart(ADAPTER, 'housing', 'mount', [0, p.mount + ADAPTER[1] / 2, 0]));
    if (p.mount - body.top > 0.002) parts.push(rodPart(STEM_RADIUS, body.top, p.mount, 'housing', 'mount'));
  }
  return { model: { parts, pivot: [0, 0, 0], emitterArea: body.emitterArea.down || body.emitterArea.up, emitterAreaUp: body.emitterArea.up || body.emitterArea.down }, angles };
}
