import type { Rgb, SurfaceName, Vec3 } from '../core/model/lightingScene/lightingScene';
import { BOX_FACES, facePoint, type BoxFace } from './boxGeometry';
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

/** How far a point may lie from a surface to count as on it, metres (docs/scene-format.md probe contract: 1 cm). */
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
    throw new ReferenceInputError(`sample point [${point.join(', ')}]: not on ${surface ?? 'any surface'} of the ${extent.join(' × ')} m room (tolerance ${SURFACE_TOLERANCE} m)`);
  }
  const face = BOX_FACES[best];
  // Project onto the face and keep a hair inside it, so the point never sits
  // exactly on a neighbouring face's edge where the contour integral is singular.
  const inset = 1e-7 * Math.max(...extent);
  const u = Math.min(Math.max(point[face.uAxis], inset), extent[face.uAxis] - inset);
  const v = Math.min(Math.max(point[face.vAxis], inset), extent[face.vAxis] - inset);
  const p = facePoint(result.grid, face, u, v);

  const directRgb = directIlluminanceAt(result.sources, p, face.normal);
  const indirectRgb = gatherIndirect(result, p, face.normal, face);
  const totalRgb: Rgb = [directRgb[0] + indirectRgb[0], directRgb[1] + indirectRgb[1], directRgb[2] + indirectRgb[2]];
  return { surface: face.name, direct: y(directRgb), indirect: y(indirectRgb), total: y(totalRgb), directRgb, indirectRgb, totalRgb };
}

/** Patches closer than this many patch diagonals are gathered in NEAR_SPLIT² parts with interpolated exitance. */
const NEAR_DIAGONALS = 2;
const NEAR_SPLIT = 4;

/**
 * Final gather of indirect illuminance at p. Far patches count with their mean
 * exitance. Near ones (the corner of the room, the patches around a point close
 * to another wall) are split and their exitance interpolated bilinearly between
 * patch centres (extrapolated over the outer half patch), which takes the
 * gather from first to about second order in the patch size where the exitance
 * varies fastest.
 */
function gatherIndirect(result: ReferenceResult, p: Vec3, n: Vec3, face: BoxFace): Rgb {
  const out: Rgb = [0, 0, 0];
  const corners: Vec3[] = [
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0],
  ];
  const m: Rgb = [0, 0, 0];
  for (const q of BOX_FACES) {
    if (q === face) continue;
    const s = result.surfaces[q.name];
    const rho = s.reflectance;
    if (rho[0] === 0 && rho[1] === 0 && rho[2] === 0) continue;
    const plane = q.side === 0 ? 0 : result.grid.extent[q.axis];
    const near = NEAR_DIAGONALS * Math.hypot(s.du, s.dv);
    const rect = (u0: number, v0: number, du: number, dv: number): number => {
      const set = (c: Vec3, u: number, v: number): void => {
        c[q.axis] = plane;
        c[q.uAxis] = u;
        c[q.vAxis] = v;
      };
      set(corners[0], u0, v0);
      set(corners[1], u0 + du, v0);
      set(corners[2], u0 + du, v0 + dv);
      set(corners[3], u0, v0 + dv);
      return pointToPolygonFormFactor(p, n, corners);
    };
    for (let iv = 0; iv < s.nv; iv++) {
      for (let iu = 0; iu < s.nu; iu++) {
        const u0 = iu * s.du;
        const v0 = iv * s.dv;
        const cu = u0 + 0.5 * s.du - p[q.uAxis];
        const cv = v0 + 0.5 * s.dv - p[q.vAxis];
        const dist = Math.hypot(cu, cv, plane - p[q.axis]);
        if (dist > near) {
          const f = rect(u0, v0, s.du, s.dv);
          const k = 3 * (iv * s.nu + iu);
          for (let c = 0; c < 3; c++) out[c] += f * rho[c] * s.totalRgb[k + c];
          continue;
        }
        const su = s.du / NEAR_SPLIT;
        const sv = s.dv / NEAR_SPLIT;
        for (let a = 0; a < NEAR_SPLIT; a++) {
          for (let b = 0; b < NEAR_SPLIT; b++) {
            const f = rect(u0 + a * su, v0 + b * sv, su, sv);
            interpolatedTotal(s, u0 + (a + 0.5) * su, v0 + (b + 0.5) * sv, m);
            for (let c = 0; c < 3; c++) out[c] += f * rho[c] * m[c];
          }
        }
      }
    }
  }
  return out;
}

/**
 * Bilinear interpolation of patch-mean total illuminance (RGB) between patch
 * centres, extrapolated linearly over the outer half patch (where a room corner
 * makes it change fastest), never below zero.
 */
function interpolatedTotal(s: ReferenceResult['surfaces'][SurfaceName], u: number, v: number, out: Rgb): void {
  const fu = Math.min(Math.max(u / s.du - 0.5, -0.5), s.nu - 0.5);
  const fv = Math.min(Math.max(v / s.dv - 0.5, -0.5), s.nv - 0.5);
  const iu = Math.min(Math.max(Math.floor(fu), 0), Math.max(s.nu - 2, 0));
  const iv = Math.min(Math.max(Math.floor(fv), 0), Math.max(s.nv - 2, 0));
  const tu = s.nu > 1 ? fu - iu : 0;
  const tv = s.nv > 1 ? fv - iv : 0;
  const iu1 = Math.min(iu + 1, s.nu - 1);
  const iv1 = Math.min(iv + 1, s.nv - 1);
  for (let c = 0; c < 3; c++) {
    const at = (a: number, b: number): number => s.totalRgb[3 * (b * s.nu + a) + c];
    const value = (at(iu, iv) * (1 - tu) + at(iu1, iv) * tu) * (1 - tv) + (at(iu, iv1) * (1 - tu) + at(iu1, iv1) * tu) * tv;
    out[c] = Math.max(value, 0);
  }
}
