import type { Rgb, SurfaceName, Vec3 } from '../model/lightingScene';
import { BOX_FACES, facePoint } from './boxGeometry';
import { directIlluminanceAt } from './directIlluminance';
import { pointToPolygonFormFactor } from './pointToPolygonFormFactor';
import { ReferenceInputError } from './referenceInputError';
import { LUMINANCE_WEIGHTS, type ReferenceResult } from './solveBoxReference';

export interface ReferenceSample {
  surface: SurfaceName;
  /** Lux, luminance-weighted (Y). */
  direct: number;
  indirect: number;
  total: number;
  directRgb: Rgb;
  indirectRgb: Rgb;
  totalRgb: Rgb;
}

/** How far a point may lie from a surface to count as on it, metres (DESIGN.md probe contract: 1 cm). */
export const SURFACE_TOLERANCE = 0.01;

const y = (c: Rgb): number => LUMINANCE_WEIGHTS[0] * c[0] + LUMINANCE_WEIGHTS[1] * c[1] + LUMINANCE_WEIGHTS[2] * c[2];

/**
 * Illuminance at an arbitrary surface point of a solved box.
 *
 * Direct light is evaluated exactly at the point (no patch averaging); indirect
 * light by a final gather, E_ind(p) = Σ_j F(dA_p → patch_j) · M_j, with the exact
 * point-to-rectangle factor (Lambert's contour integral) and the converged patch
 * exitances M_j = ρ_j·E_j. So the only discretisation left is M being constant per
 * patch, which smooths out in the gather.
 *
 * `surface` picks the face when the point is near an edge; otherwise the nearest
 * face within SURFACE_TOLERANCE is used.
 */
export function sampleReference(result: ReferenceResult, point: Vec3, surface?: SurfaceName): ReferenceSample {
  const { extent } = result.grid;
  if (point.length !== 3 || !point.every(Number.isFinite)) {
    throw new ReferenceInputError(`sample point [${point.join(', ')}]: expected three finite numbers`);
  }
  let best = -1;
  let bestDist = Infinity;
  BOX_FACES.forEach((f, fi) => {
    if (surface !== undefined && f.name !== surface) return;
    const plane = f.side === 0 ? 0 : extent[f.axis];
    let dist = Math.abs(point[f.axis] - plane);
    for (const a of [f.uAxis, f.vAxis]) dist = Math.max(dist, -point[a], point[a] - extent[a]);
    if (dist < bestDist) {
      bestDist = dist;
      best = fi;
    }
  });
  if (best < 0 || bestDist > SURFACE_TOLERANCE) {
    throw new ReferenceInputError(
      `sample point [${point.join(', ')}]: not on ${surface ?? 'any surface'} of the ${extent.join(' × ')} m room (tolerance ${SURFACE_TOLERANCE} m)`,
    );
  }
  const face = BOX_FACES[best];
  // Project onto the face and keep a hair inside it, so the point never sits
  // exactly on a neighbouring face's edge where the contour integral is singular.
  const inset = 1e-7 * Math.max(...extent);
  const u = Math.min(Math.max(point[face.uAxis], inset), extent[face.uAxis] - inset);
  const v = Math.min(Math.max(point[face.vAxis], inset), extent[face.vAxis] - inset);
  const p = facePoint(result.grid, face, u, v);

  const directRgb = directIlluminanceAt(result.sources, p, face.normal);
  const indirectRgb: Rgb = [0, 0, 0];
  for (const q of BOX_FACES) {
    if (q === face) continue;
    const s = result.surfaces[q.name];
    const rho = s.reflectance;
    if (rho[0] === 0 && rho[1] === 0 && rho[2] === 0) continue;
    for (let iv = 0; iv < s.nv; iv++) {
      for (let iu = 0; iu < s.nu; iu++) {
        const u0 = iu * s.du;
        const v0 = iv * s.dv;
        const corners = [
          facePoint(result.grid, q, u0, v0),
          facePoint(result.grid, q, u0 + s.du, v0),
          facePoint(result.grid, q, u0 + s.du, v0 + s.dv),
          facePoint(result.grid, q, u0, v0 + s.dv),
        ];
        const f = pointToPolygonFormFactor(p, face.normal, corners);
        const k = 3 * (iv * s.nu + iu);
        for (let c = 0; c < 3; c++) indirectRgb[c] += f * rho[c] * s.totalRgb[k + c];
      }
    }
  }
  const totalRgb: Rgb = [directRgb[0] + indirectRgb[0], directRgb[1] + indirectRgb[1], directRgb[2] + indirectRgb[2]];
  return { surface: face.name, direct: y(directRgb), indirect: y(indirectRgb), total: y(totalRgb), directRgb, indirectRgb, totalRgb };
}
