/**
 * Direct daylight at one point of a surface (p, unit normal n), bake coordinates: the sky and
 * the ground seen through each window, and the sun's beam leaving through one.
 *
 * Sky and ground: E = ∫_W L(d) τ(θ_w) cos θ_p cos θ_w / r² dA over the window's rectangle
 * (CIE 171:2006 §5.9's sky component, the window as an area source). The rectangle is cut at
 * p's horizon plane y = p_y (above it p sees the sky, below it the ground, whose luminance is
 * uniform), and each part into cells no larger than distance / CELLS_PER_DISTANCE, between 2 and
 * MAX_CELLS a side; the midpoint rule's relative error is then about (h/r)² / 24 ≤ 0.1 % (h the
 * cell, r the distance). In a room that is not convex, or with objects, each cell's centre is
 * seen or not along a ray through the scene's BVH (the room's surfaces and the objects); in a
 * convex empty room every segment between two of its points stays inside, so no ray is cast.
 *
 * Sun: a parallel beam; E = E_n τ(θ_w) max(0, n·s) where the ray from p toward the sun leaves
 * through a window (its first crossing of a window plane inside the rectangle) and nothing of the
 * scene stands in between.
 */
import { glazingTransmittance } from '../../../core/daylight/glazing';
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { BakeDaylight } from './bakeDaylight';
import type { BakeWindow } from './daylightWindows';

/** Cells per unit of distance/size: cell edge ≤ distance / 6. */
export const CELLS_PER_DISTANCE = 6;
export const MAX_CELLS = 32;
/** A partly hidden window: this many times the columns and rows (at most MAX_REFINED columns). */
const REFINE_COLUMNS = 8;
const REFINE_ROWS = 2;
const MAX_REFINED = 128;
const MIN_OCCLUDED_COLUMNS = 8;
const MIN_OCCLUDED_ROWS = 4;
/** Rays start this far off their surface along its normal and stop this much short of their target (the objects' rule, docs/baker.md "Objects: passes"). */
const SURFACE_OFFSET = 1e-4;
const SHORT_OF_TARGET = 1e-4;

/** Whether the segment from `origin` along `dir` (t in (0, tMax)) meets the scene. */
export type Occluded = (origin: Vec3, dir: Vec3, tMax: number) => boolean;

export interface DaylightPointContext {
  daylight: BakeDaylight;
  windows: readonly BakeWindow[];
  /** null: nothing can block a sight line (a convex room without objects). */
  occluded: Occluded | null;
}

const dot = (a: readonly number[], b: readonly number[]): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function blocked(ctx: DaylightPointContext, origin: Vec3, q: Vec3): boolean {
  if (!ctx.occluded) return false;
  return ctx.occluded(origin, [q[0] - origin[0], q[1] - origin[1], q[2] - origin[2]], 1 - SHORT_OF_TARGET);
}

/** Distance from p to the window's rectangle. */
function distanceToWindow(w: BakeWindow, p: Vec3): number {
  const d: Vec3 = [p[0] - w.corner[0], p[1] - w.corner[1], p[2] - w.corner[2]];
  const la = Math.hypot(...w.edgeA);
  const lb = Math.hypot(...w.edgeB);
  const a = Math.min(Math.max(dot(d, w.edgeA) / la, 0), la);
  const b = Math.min(Math.max(dot(d, w.edgeB) / lb, 0), lb);
  const q = [w.corner[0] + (a / la) * w.edgeA[0] + (b / lb) * w.edgeB[0], w.corner[1] + (a / la) * w.edgeA[1] + (b / lb) * w.edgeB[1], w.corner[2] + (a / la) * w.edgeA[2] + (b / lb) * w.edgeB[2]];
  return Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

const cellsFor = (size: number, distance: number): number => Math.min(MAX_CELLS, Math.max(2, Math.ceil((CELLS_PER_DISTANCE * size) / Math.max(distance, 1e-9))));

/**
 * Sky and ground through one window over b in [b0, b1] (a fraction of edgeB), by the midpoint
 * rule on na × nb cells. Returns the sum and whether the cells' visibility was mixed (some seen,
 * some hidden): then an edge of what blocks them crosses the window.
 */
function skyOverCells(ctx: DaylightPointContext, w: BakeWindow, p: Vec3, n: Vec3, origin: Vec3, b0: number, b1: number, na: number, nb: number): { e: number; mixed: boolean } {
  const cellArea = (w.area * (b1 - b0)) / (na * nb);
  const { sky, groundLuminance } = ctx.daylight;
  let sum = 0;
  let seen = 0;
  let hidden = 0;
  for (let j = 0; j < nb; j++) {
    const b = b0 + ((j + 0.5) / nb) * (b1 - b0);
    for (let i = 0; i < na; i++) {
      const a = (i + 0.5) / na;
      const q: Vec3 = [w.corner[0] + a * w.edgeA[0] + b * w.edgeB[0], w.corner[1] + a * w.edgeA[1] + b * w.edgeB[1], w.corner[2] + a * w.edgeA[2] + b * w.edgeB[2]];
      const d: Vec3 = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
      const r2 = dot(d, d);
      const r = Math.sqrt(r2);
      const cosP = dot(d, n) / r;
      const cosW = -dot(d, w.inward) / r;
      if (cosP <= 0 || cosW <= 0) continue;
      const unit: Vec3 = [d[0] / r, d[1] / r, d[2] / r];
      const luminance = unit[1] > 0 ? (sky ? sky.luminance(unit) : 0) : groundLuminance;
      if (luminance <= 0) continue;
      if (blocked(ctx, origin, q)) {
        hidden++;
        continue;
      }
      seen++;
      sum += (luminance * glazingTransmittance(w.glazing, cosW) * cosP * cosW) / r2;
    }
  }
  return { e: sum * cellArea, mixed: seen > 0 && hidden > 0 };
}

/** Whether a corner of the band (inset by 1e-3 of the window) is seen differently from what the cells found (`seen`: some cell was seen). */
function cornersDisagree(ctx: DaylightPointContext, w: BakeWindow, origin: Vec3, b0: number, b1: number, seen: boolean): boolean {
  const inset = 1e-3;
  for (const a of [inset, 1 - inset]) {
    for (const b of [b0 + inset * (b1 - b0), b1 - inset * (b1 - b0)]) {
      const q: Vec3 = [w.corner[0] + a * w.edgeA[0] + b * w.edgeB[0], w.corner[1] + a * w.edgeA[1] + b * w.edgeB[1], w.corner[2] + a * w.edgeA[2] + b * w.edgeB[2]];
      if (blocked(ctx, origin, q) === seen) return true;
    }
  }
  return false;
}

/**
 * One band of the window: cells sized by the distance; where the room (an inner corner, always a
 * vertical edge) or an object hides part of the window, the band again with REFINE_COLUMNS times
 * the columns and REFINE_ROWS times the rows, so the cut is resolved to a small fraction of the
 * window (midpoint samples of a partly hidden window are otherwise off by up to half a cell).
 */
function skyOverBand(ctx: DaylightPointContext, w: BakeWindow, p: Vec3, n: Vec3, origin: Vec3, b0: number, b1: number, distance: number): number {
  // Where sight lines can be blocked, at least MIN_OCCLUDED_COLUMNS × MIN_OCCLUDED_ROWS cells, and the band's corners are looked at too, so that a small visible or hidden part is not missed.
  const occludable = ctx.occluded !== null;
  const na = Math.max(cellsFor(Math.hypot(...w.edgeA), distance), occludable ? MIN_OCCLUDED_COLUMNS : 0);
  const nb = Math.max(cellsFor(Math.hypot(...w.edgeB) * (b1 - b0), distance), occludable ? MIN_OCCLUDED_ROWS : 0);
  const coarse = skyOverCells(ctx, w, p, n, origin, b0, b1, na, nb);
  if (!occludable) return coarse.e;
  if (!coarse.mixed && !cornersDisagree(ctx, w, origin, b0, b1, coarse.e > 0)) return coarse.e;
  return skyOverCells(ctx, w, p, n, origin, b0, b1, Math.min(REFINE_COLUMNS * na, MAX_REFINED), Math.min(REFINE_ROWS * nb, MAX_CELLS)).e;
}

/** Sky and ground illuminance at p (lux) through every window. */
export function skyDaylightAt(ctx: DaylightPointContext, p: Vec3, n: Vec3): number {
  const origin: Vec3 = [p[0] + n[0] * SURFACE_OFFSET, p[1] + n[1] * SURFACE_OFFSET, p[2] + n[2] * SURFACE_OFFSET];
  let e = 0;
  for (const w of ctx.windows) {
    if (dot([p[0] - w.corner[0], p[1] - w.corner[1], p[2] - w.corner[2]], w.inward) <= 1e-9) continue;
    const distance = distanceToWindow(w, p);
    // The horizon plane y = p_y cuts edgeB (vertical) at b*: below it the ground, above it the sky.
    const horizon = (p[1] - w.corner[1]) / w.edgeB[1];
    if (horizon > 0 && horizon < 1) e += skyOverBand(ctx, w, p, n, origin, 0, horizon, distance) + skyOverBand(ctx, w, p, n, origin, horizon, 1, distance);
    else e += skyOverBand(ctx, w, p, n, origin, 0, 1, distance);
  }
  return e;
}

/** The sun's illuminance at p (lux): the beam through the first window plane it crosses inside a window, if nothing blocks it. */
export function sunDaylightAt(ctx: DaylightPointContext, p: Vec3, n: Vec3): number {
  const sun = ctx.daylight.sun;
  if (!sun || sun.normalIlluminance <= 0) return 0;
  const s = sun.direction;
  const cosP = dot(s, n);
  if (cosP <= 0) return 0;
  let best: { t: number; q: Vec3; cosW: number; w: BakeWindow } | null = null;
  for (const w of ctx.windows) {
    const cosW = -dot(s, w.inward);
    const height = dot([p[0] - w.corner[0], p[1] - w.corner[1], p[2] - w.corner[2]], w.inward);
    if (cosW <= 0 || height <= 1e-9) continue;
    const t = height / cosW;
    if (best && t >= best.t) continue;
    const q: Vec3 = [p[0] + t * s[0], p[1] + t * s[1], p[2] + t * s[2]];
    const rel = [q[0] - w.corner[0], q[1] - w.corner[1], q[2] - w.corner[2]];
    const a = dot(rel, w.edgeA) / dot(w.edgeA, w.edgeA);
    const b = dot(rel, w.edgeB) / dot(w.edgeB, w.edgeB);
    if (a >= 0 && a <= 1 && b >= 0 && b <= 1) best = { t, q, cosW, w };
  }
  if (!best) return 0;
  const origin: Vec3 = [p[0] + n[0] * SURFACE_OFFSET, p[1] + n[1] * SURFACE_OFFSET, p[2] + n[2] * SURFACE_OFFSET];
  if (blocked(ctx, origin, best.q)) return 0;
  return sun.normalIlluminance * glazingTransmittance(best.w.glazing, best.cosW) * cosP;
}
