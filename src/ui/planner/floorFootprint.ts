import { intensity } from '../../core/photometry/intensity';
import type { Photometry } from '../../core/photometry/types';

/**
 * Where a luminaire puts most of its light on the floor, from its measured photometry: the
 * region where the direct horizontal illuminance is at least half its maximum.
 *
 * A luminaire at height h above the floor, hanging straight down, lights the floor point at
 * horizontal distance r in direction C (luminaire frame) with
 *
 *   E(r, C) = I(γ, C) · cos³γ / h²,   γ = atan(r / h)
 *
 * (inverse-square law with the cosine of incidence, CIE 171:2006 test case 5.2). Because
 * E depends on r only through r/h, the region {E ≥ ½·E_max} is the same shape at every height,
 * scaled by h: it is computed once per photometric file for h = 1 and scaled by the caller.
 * The region is traced as a star-shaped polygon around the brightest floor point, so
 * off-axis optics (wall washers) give a shifted patch rather than a circle under the lamp.
 *
 * Coordinates are the luminaire's horizontal frame: x along C0, y toward C90 (which is local
 * −z, counterclockwise seen from above: docs/scene-format.md "Units and frames").
 */

/** Contour level as a fraction of the floor maximum. */
export const FOOTPRINT_LEVEL = 0.5;
/** Rays flatter than this never meet the floor within a room; the trace stops there. */
export const MAX_GAMMA_DEG = 80;

const RAYS = 72;
const SEARCH_GAMMA_STEP = 0.5;
const SEARCH_C_STEP = 5;
const MARCH_STEPS = 2000;

const rad = (d: number) => (d * Math.PI) / 180;

/** Horizontal illuminance on the floor at (u, v) in units of h (luminaire at height 1). */
function floorE(ph: Photometry, u: number, v: number): number {
  const r = Math.hypot(u, v);
  const gamma = Math.atan(r);
  const c = r > 0 ? (Math.atan2(v, u) * 180) / Math.PI : 0;
  const cos = Math.cos(gamma);
  return intensity(ph, (gamma * 180) / Math.PI, c) * cos * cos * cos;
}

export interface FloorFootprint {
  /** Boundary points in units of mounting height, luminaire horizontal frame (x along C0, y toward C90). */
  polygon: [number, number][];
  /** The brightest floor point, same units. */
  peak: [number, number];
}

/** The half-maximum floor footprint for a luminaire 1 unit above the floor; null if it sends no light down. */
export function floorFootprint(ph: Photometry): FloorFootprint | null {
  let eMax = 0;
  let peak: [number, number] = [0, 0];
  for (let g = 0; g <= MAX_GAMMA_DEG; g += SEARCH_GAMMA_STEP) {
    const r = Math.tan(rad(g));
    for (let c = 0; c < 360; c += g === 0 ? 360 : SEARCH_C_STEP) {
      const u = r * Math.cos(rad(c));
      const v = r * Math.sin(rad(c));
      const e = floorE(ph, u, v);
      if (e > eMax) {
        eMax = e;
        peak = [u, v];
      }
    }
  }
  if (!(eMax > 0)) return null;
  const level = FOOTPRINT_LEVEL * eMax;
  const rMax = Math.tan(rad(MAX_GAMMA_DEG));
  const step = (2 * rMax) / MARCH_STEPS;
  const polygon: [number, number][] = [];
  for (let k = 0; k < RAYS; k++) {
    const a = (2 * Math.PI * k) / RAYS;
    const du = Math.cos(a);
    const dv = Math.sin(a);
    let prevT = 0;
    let prevE = eMax;
    let t = step;
    let edge = 0;
    for (; t <= 2 * rMax; t += step) {
      const u = peak[0] + du * t;
      const v = peak[1] + dv * t;
      if (Math.hypot(u, v) > rMax) {
        edge = prevT;
        break;
      }
      const e = floorE(ph, u, v);
      if (e < level) {
        // Linear interpolation of the crossing between the last two samples.
        edge = prevT + ((prevE - level) / (prevE - e)) * (t - prevT);
        break;
      }
      prevT = t;
      prevE = e;
      edge = t;
    }
    polygon.push([peak[0] + du * edge, peak[1] + dv * edge]);
  }
  return { polygon, peak };
}
