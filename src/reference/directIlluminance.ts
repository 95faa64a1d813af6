import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';
import { candelaAt } from './candelaAt';
import type { ReferencePointSource } from './pointSources';

const RAD_TO_DEG = 180 / Math.PI;

/**
 * Direct illuminance (lux, per RGB channel) at surface point q with unit normal n:
 * E = Σ I(γ, C)·cos(incidence)/d² over the sources in front of the surface
 * (CIE 171:2006 §5.2; inverse-square and cosine laws). An empty box room has no
 * occluders, so no visibility test is needed.
 */
export function directIlluminanceAt(sources: readonly ReferencePointSource[], q: Vec3, n: Vec3, out: Rgb = [0, 0, 0]): Rgb {
  out[0] = 0;
  out[1] = 0;
  out[2] = 0;
  for (const s of sources) {
    const dx = q[0] - s.position[0];
    const dy = q[1] - s.position[1];
    const dz = q[2] - s.position[2];
    const d2 = dx * dx + dy * dy + dz * dz;
    if (!(d2 > 0)) continue;
    const d = Math.sqrt(d2);
    // cos of incidence: the direction from q to the lamp against the surface normal.
    const cos = -(dx * n[0] + dy * n[1] + dz * n[2]) / d;
    if (!(cos > 0)) continue;
    // Direction lamp → q in the luminaire frame (s.toLocal · d), then its type C angles
    // (photometricAngles in luminaireRotation.ts, inlined: this is the hot loop).
    const m = s.toLocal;
    const lx = m[0] * dx + m[1] * dy + m[2] * dz;
    const ly = m[3] * dx + m[4] * dy + m[5] * dz;
    const lz = m[6] * dx + m[7] * dy + m[8] * dz;
    // A face of a tall opening lights only its own hemisphere (pointSources.ts).
    if (s.hemisphere * ly < 0) continue;
    const gammaDeg = Math.atan2(Math.sqrt(lx * lx + lz * lz), -ly) * RAD_TO_DEG;
    let cDeg = Math.atan2(-lz, lx) * RAD_TO_DEG;
    if (cDeg < 0) cDeg += 360;
    const e = (candelaAt(s.photometry, gammaDeg, cDeg) * cos) / d2;
    out[0] += e * s.scale[0];
    out[1] += e * s.scale[1];
    out[2] += e * s.scale[2];
  }
  return out;
}

// 3-point Gauss–Legendre nodes and weights on [0, 1] (Abramowitz & Stegun 25.4.29).
const GL_X = [0.5 - Math.sqrt(0.15), 0.5, 0.5 + Math.sqrt(0.15)];
const GL_W = [5 / 18, 8 / 18, 5 / 18];

export interface RectOnFace {
  /** Axis of the face normal and its coordinate. */
  axis: 0 | 1 | 2;
  plane: number;
  uAxis: 0 | 1 | 2;
  vAxis: 0 | 1 | 2;
  normal: Vec3;
}

/** Mean direct illuminance over [u0,u1]×[v0,v1] by a 3×3 Gauss–Legendre rule. */
function gaussMean(sources: readonly ReferencePointSource[], f: RectOnFace, u0: number, u1: number, v0: number, v1: number): Rgb {
  const acc: Rgb = [0, 0, 0];
  const e: Rgb = [0, 0, 0];
  const q: Vec3 = [0, 0, 0];
  q[f.axis] = f.plane;
  for (let i = 0; i < 3; i++) {
    q[f.uAxis] = u0 + (u1 - u0) * GL_X[i];
    for (let j = 0; j < 3; j++) {
      q[f.vAxis] = v0 + (v1 - v0) * GL_X[j];
      directIlluminanceAt(sources, q, f.normal, e);
      const w = GL_W[i] * GL_W[j];
      acc[0] += w * e[0];
      acc[1] += w * e[1];
      acc[2] += w * e[2];
    }
  }
  return acc;
}

/** The cell-angle rule refines at most this deep (a cell of 1/16 of the patch edge); the error rule may go deeper. */
const ANGLE_DEPTH = 4;

export interface PatchAverageOptions {
  /** Relative tolerance of the adaptive rule. */
  relTol: number;
  /** Absolute tolerance in lux (the scale below which differences do not matter). */
  absTol: number;
  /** Deepest quadtree split of a patch. */
  maxDepth: number;
  /** Largest angle (radians) one quadrature cell may subtend from a source, so narrow beams cannot slip between nodes. */
  maxCellAngle: number;
}

/**
 * Mean direct illuminance over a rectangle of a face (lux, RGB): adaptive
 * quadtree of 3×3 Gauss–Legendre rules, split while the rule on the rectangle and
 * on its four quarters disagree, or while a cell subtends more than
 * `maxCellAngle` from a source (a 1° spot must not fall between nodes).
 */
export function patchMeanDirect(sources: readonly ReferencePointSource[], f: RectOnFace, u0: number, u1: number, v0: number, v1: number, opt: PatchAverageOptions): Rgb {
  const out: Rgb = [0, 0, 0];
  const visit = (a0: number, a1: number, b0: number, b1: number, depth: number, whole: Rgb): void => {
    const am = 0.5 * (a0 + a1);
    const bm = 0.5 * (b0 + b1);
    const quarters = [gaussMean(sources, f, a0, am, b0, bm), gaussMean(sources, f, am, a1, b0, bm), gaussMean(sources, f, a0, am, bm, b1), gaussMean(sources, f, am, a1, bm, b1)];
    const fine: Rgb = [0, 0, 0];
    for (const q of quarters) for (let c = 0; c < 3; c++) fine[c] += 0.25 * q[c];
    let converged = true;
    for (let c = 0; c < 3; c++) {
      if (Math.abs(fine[c] - whole[c]) > opt.relTol * Math.abs(fine[c]) + opt.absTol) converged = false;
    }
    if (converged && depth < ANGLE_DEPTH) converged = !tooCoarse(sources, f, a0, a1, b0, b1, opt.maxCellAngle);
    const share = ((a1 - a0) * (b1 - b0)) / ((u1 - u0) * (v1 - v0));
    if (converged || depth >= opt.maxDepth) {
      for (let c = 0; c < 3; c++) out[c] += share * fine[c];
      return;
    }
    visit(a0, am, b0, bm, depth + 1, quarters[0]);
    visit(am, a1, b0, bm, depth + 1, quarters[1]);
    visit(a0, am, bm, b1, depth + 1, quarters[2]);
    visit(am, a1, bm, b1, depth + 1, quarters[3]);
  };
  visit(u0, u1, v0, v1, 0, gaussMean(sources, f, u0, u1, v0, v1));
  return out;
}

/** Does a quarter cell of the rectangle subtend more than maxAngle from some source in front of it? */
function tooCoarse(sources: readonly ReferencePointSource[], f: RectOnFace, a0: number, a1: number, b0: number, b1: number, maxAngle: number): boolean {
  const half = 0.5 * Math.hypot(a1 - a0, b1 - b0);
  const c: Vec3 = [0, 0, 0];
  c[f.axis] = f.plane;
  c[f.uAxis] = 0.5 * (a0 + a1);
  c[f.vAxis] = 0.5 * (b0 + b1);
  for (const s of sources) {
    const dist = Math.hypot(s.position[0] - c[0], s.position[1] - c[1], s.position[2] - c[2]);
    // A quarter cell has half the diagonal of this one.
    if (half > maxAngle * Math.max(dist - half, 1e-9)) return true;
  }
  return false;
}
