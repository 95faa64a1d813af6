/**
 * The 2D light footprint indicator (the configurator paper's planned "light cone indicator in the 2D
 * view"): where a module's beam meets the floor, as an ellipse in plan coordinates.
 *
 * A cone of full beam angle β whose axis points straight down from height h meets the floor
 * in a circle of radius h·tan(β/2). A module that is itself long (a linear diffuser of length
 * L) spreads that circle along its length: the footprint's semi-axis along the rail is
 * L/2 + h·tan(β_along/2). A module tilted by t about the rail axis (a wall washer aimed at a
 * wall) lights the floor between h·tan(t − β/2) and h·tan(t + β/2) across the rail, which
 * gives the centre shift and the across semi-axis exactly for the two edge rays; along the
 * rail we use the slant distance h/cos t in place of h, a first-order estimate that is
 * exact at t = 0. It is an indicator, not photometry: the 3D view shows the measured light.
 */

import type { PlanPoint } from './viewTransform';

/** Rays flatter than this never meet a finite floor; capping keeps the ellipse finite. */
export const MAX_HALF_ANGLE_DEG = 75;

export interface FootprintInput {
  /** Module centre in the plan (metres). */
  center: PlanPoint;
  /** Direction of the rail in the plan, degrees, measured from +x towards +z (screen clockwise). */
  axisDeg: number;
  /** Length the module occupies along the rail, metres (0 for a point source). */
  length: number;
  /** Height of the light-emitting centre above the floor, metres. */
  height: number;
  /** Full beam angle in the plane along the rail, degrees. */
  beamAlongDeg: number;
  /** Full beam angle across the rail, degrees. */
  beamAcrossDeg: number;
  /** Tilt of the beam axis away from nadir across the rail, degrees (positive = towards +across). */
  tiltDeg?: number;
}

export interface FootprintEllipse {
  center: PlanPoint;
  /** Semi-axis along the rail, metres. */
  rx: number;
  /** Semi-axis across the rail, metres. */
  ry: number;
  /** Rotation of the rx axis, degrees from +x towards +z (SVG rotate() convention). */
  rotationDeg: number;
}

const rad = (deg: number) => (deg * Math.PI) / 180;
const clampHalf = (deg: number) => Math.max(-MAX_HALF_ANGLE_DEG, Math.min(MAX_HALF_ANGLE_DEG, deg));
const finiteOr = (v: number, fallback: number) => (Number.isFinite(v) ? v : fallback);

export function beamFootprint(input: FootprintInput): FootprintEllipse {
  const h = Math.max(0, finiteOr(input.height, 0));
  const length = Math.max(0, finiteOr(input.length, 0));
  const tilt = clampHalf(finiteOr(input.tiltDeg ?? 0, 0));
  const halfAlong = clampHalf(Math.max(0, finiteOr(input.beamAlongDeg, 0)) / 2);
  const halfAcross = Math.max(0, finiteOr(input.beamAcrossDeg, 0)) / 2;

  const near = h * Math.tan(rad(clampHalf(tilt - halfAcross)));
  const far = h * Math.tan(rad(clampHalf(tilt + halfAcross)));
  const shift = (near + far) / 2;
  const ry = (far - near) / 2;
  const slant = h / Math.cos(rad(tilt));
  const rx = length / 2 + slant * Math.tan(rad(halfAlong));

  const axis = rad(finiteOr(input.axisDeg, 0));
  // The across direction is the along direction turned +90° in the plan (from +x towards +z).
  const acrossX = -Math.sin(axis);
  const acrossZ = Math.cos(axis);
  return {
    center: { x: input.center.x + acrossX * shift, z: input.center.z + acrossZ * shift },
    rx,
    ry,
    rotationDeg: finiteOr(input.axisDeg, 0),
  };
}
