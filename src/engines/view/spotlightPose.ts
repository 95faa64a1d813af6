/**
 * The spotlight view's camera and drag (docs/aiming.md): a camera at the module's photometric
 * centre looking along its optical axis, "up" in the image the direction the axis moves when the
 * tilt grows, so dragging up tilts the head further out and dragging sideways pans it, as the
 * theatre report's focusing view turns the instrument under the mouse.
 */
import { aimAxis, clampAim, type AimLimits } from '../../core/model/modules/aim';
import type { ModuleAim } from '../../core/model/configuration/configuration';
import type { Vec3 } from '../../core/model/lightingScene/lightingScene';

const DEG = Math.PI / 180;

export interface SpotlightPose {
  position: Vec3;
  /** A point one metre along the axis (what the camera looks at). */
  target: Vec3;
  /** The image's up direction (unit, perpendicular to the axis). */
  up: Vec3;
  /** Vertical field of view, degrees. */
  fov: number;
}

/** Field of view that shows the whole field (10 %) cone with a margin around it, within 30°–100°. */
export function spotlightFov(fieldDeg: number): number {
  return Math.min(100, Math.max(30, 1.6 * (Number.isFinite(fieldDeg) ? fieldDeg : 60)));
}

/**
 * The pose of the spotlight view. Up is ∂axis/∂tilt = (cos t·cos a, sin t, −cos t·sin a), a = heading +
 * rotation: unit, perpendicular to the axis, and defined at tilt 0 too (the head's forward side).
 */
export function spotlightPose(position: Vec3, heading: number, aim: ModuleAim, fieldDeg: number): SpotlightPose {
  const axis = aimAxis(heading, aim);
  const t = aim.tilt * DEG;
  const a = (heading + aim.rotation) * DEG;
  return {
    position,
    target: [position[0] + axis[0], position[1] + axis[1], position[2] + axis[2]],
    up: [Math.cos(t) * Math.cos(a), Math.sin(t), -Math.cos(t) * Math.sin(a)],
    fov: spotlightFov(fieldDeg),
  };
}

/**
 * The aim after dragging (dx, dy) CSS pixels from `start` in a view `heightPx` tall with vertical
 * field of view `fovDeg`: the axis follows the pointer at the image's scale (fov / height degrees
 * per pixel), as looking around does. Up (dy < 0) tilts further out; right turns the head
 * clockwise seen from above (the view looks right: −rotation), scaled by 1 / sin(tilt) so that a pan moves the axis by the same angle at
 * any tilt (capped near straight down, where a turn only spins the image). Clamped and snapped to
 * the head's limits (clampAim) at every step, so the view stops at a limit like the real head.
 */
export function draggedAim(start: ModuleAim, dx: number, dy: number, fovDeg: number, heightPx: number, limits: AimLimits): ModuleAim {
  const perPx = fovDeg / Math.max(1, heightPx);
  const sinT = Math.max(0.25, Math.sin(start.tilt * DEG));
  return clampAim({ rotation: start.rotation - (dx * perPx) / sinT, tilt: start.tilt - dy * perPx }, limits);
}
