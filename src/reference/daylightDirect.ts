/**
 * Direct daylight in a room of any shape (issue 30), for the reference only: the sky and the
 * ground seen through each window, and the sun through it. Windows are the room's openings of
 * kind 'window' (rectangles in vertical walls, src/core/room/roomSurfaces.ts); doors and plain
 * openings let no daylight in (they lead indoors) and, like windows, let light out.
 *
 * - Sky and ground at a point p (normal n) through window W:
 *     E = ∫_W L(d)·τ(θ_W)·cos θ_p dω,
 *   L the sky's luminance above p's horizon and the ground's ρ_g (E_sky,h + E_sun,h)/π below it,
 *   τ(θ_W) the glazing at the angle to the window's normal. Quadrature: W is cut into m × m cells
 *   and each cell at p's horizon plane (y = p_y, where sky meets ground as seen from p); each
 *   piece weighs the luminance and τ toward its centroid by its exact form factor from p
 *   (Lambert's contour integral, clipped to p's front). For a uniform sky and an unglazed window
 *   every piece's weight is exact and the sum is π L × the window's form factor (the partition
 *   does not change Lambert's integral); for CIE skies and glass it is a midpoint rule in solid
 *   angle, m = 12·(window diagonal)/(distance to the window) within [8, 32]. In a non-convex room
 *   the columns of cells are cut where a wall starts to hide the window (visibleColumns).
 *   (E = π L F: F is the view factor, 1 for a whole hemisphere, where E = π L.)
 * - The sun, a parallel source toward unit s with normal illuminance E_n: at p
 *     E = E_n·τ(θ_W)·max(0, n·s)
 *   when the ray from p toward the sun leaves through W (clipped by the window's outline) and the
 *   room's walls do not stand between (roomSightlines; the ceiling and slopes never do).
 *   A patch's mean is exact in a convex room: the window's outline projected along s onto the
 *   patch's plane, clipped against the patch (Sutherland & Hodgman 1974), area ratio.
 */
import type { Glazing } from '../core/daylight/glazing';
import { glazingTransmittance } from '../core/daylight/glazing';
import type { Sky } from '../core/daylight/skies';
import type { Vec3 } from '../core/model/lightingScene/lightingScene';
import type { PlanPoint } from '../core/room/planPolygon';
import type { RoomSurface, SurfaceFrame } from '../core/room/roomSurfaces';
import { clipToFront, frontFormFactor, polygonCentroid } from './occludedFormFactor';
import { patchPieces, type RoomPatch } from './roomPatches';
import { sightClear, type RoomSightlines } from './roomSightlines';

export interface ReferenceSun {
  /** Unit vector toward the sun, room coordinates (x east, y up, z south). */
  direction: Vec3;
  /** Illuminance on a plane normal to the rays, lux. */
  normalIlluminance: number;
}

export interface DaylightWindow {
  /** The opening's index in the room input. */
  opening: number;
  /** World corners, and the same in the wall's frame. */
  polygon: Vec3[];
  frame: SurfaceFrame;
  /** [s0, s1, t0, t1] of the rectangle in the wall's frame. */
  bounds: [number, number, number, number];
  /** The wall's unit normal into the room. */
  inward: Vec3;
  area: number;
  glazing: Glazing;
}

export interface DaylightContext {
  windows: DaylightWindow[];
  sight: RoomSightlines;
  sky: Sky | null;
  sun: ReferenceSun | null;
  /** cd/m² of the ground seen below the horizon. */
  groundLuminance: number;
}

const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: readonly number[], b: readonly number[]): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const toWorld = (f: SurfaceFrame, s: number, t: number): Vec3 => [f.origin[0] + s * f.u[0] + t * f.v[0], f.origin[1] + s * f.u[1] + t * f.v[1], f.origin[2] + s * f.u[2] + t * f.v[2]];
const toFrame = (f: SurfaceFrame, p: Vec3): PlanPoint => {
  const d = sub(p, f.origin);
  return [dot(d, f.u), dot(d, f.v)];
};

/** The windows of a room's surfaces, each with its glazing (by the opening's input index; absent: open). */
export function daylightWindows(surfaces: readonly RoomSurface[], glazing: (opening: number) => Glazing): DaylightWindow[] {
  const out: DaylightWindow[] = [];
  for (const s of surfaces) {
    for (const o of s.openings) {
      if (o.kind !== 'window') continue;
      const ss = o.polygon2d.map((p) => p[0]);
      const ts = o.polygon2d.map((p) => p[1]);
      out.push({
        opening: o.inputIndex,
        polygon: o.polygon.map((p): Vec3 => [p[0], p[1], p[2]]),
        frame: s.frame,
        bounds: [Math.min(...ss), Math.max(...ss), Math.min(...ts), Math.max(...ts)],
        inward: [...s.inward],
        area: o.area,
        glazing: glazing(o.inputIndex),
      });
    }
  }
  return out;
}

/** Distance from p to the window's rectangle. */
function distanceToWindow(w: DaylightWindow, p: Vec3): number {
  const [s, t] = toFrame(w.frame, p);
  const h = dot(sub(p, w.frame.origin), w.inward);
  const ds = Math.max(w.bounds[0] - s, 0, s - w.bounds[1]);
  const dt = Math.max(w.bounds[2] - t, 0, t - w.bounds[3]);
  return Math.hypot(h, ds, dt);
}

const UP: Vec3 = [0, 1, 0];
const DOWN: Vec3 = [0, -1, 0];

/**
 * The window's columns [s_a, s_b] (m equal ones across its width) that p sees. Sight lines are
 * decided in plan (roomSightlines.ts) and the window stands in a vertical wall, so whether p sees
 * a window point depends only on its s along the wall: in a non-convex room a column whose two
 * sides disagree is cut where the view changes (bisection to 1e-9 of the width), so the part of
 * the window a wall hides is cut off exactly, not by samples.
 */
function visibleColumns(ctx: DaylightContext, w: DaylightWindow, p: Vec3, n: Vec3, m: number): [number, number][] {
  const [s0, s1, t0, t1] = w.bounds;
  const tMid = (t0 + t1) / 2;
  const width = s1 - s0;
  const columns: [number, number][] = [];
  for (let i = 0; i < m; i++) columns.push([s0 + (width * i) / m, s0 + (width * (i + 1)) / m]);
  if (ctx.sight.convex) return columns;
  const sees = (s: number): boolean => sightClear(ctx.sight, p, n, toWorld(w.frame, s, tMid), w.inward);
  const inset = width * 1e-9;
  const out: [number, number][] = [];
  for (const [a, b] of columns) {
    const va = sees(a + inset);
    const vb = sees(b - inset);
    if (va === vb) {
      if (va && sees((a + b) / 2)) out.push([a, b]);
      continue;
    }
    let lo = a + inset;
    let hi = b - inset;
    while (hi - lo > inset) {
      const mid = (lo + hi) / 2;
      if (sees(mid) === va) lo = mid;
      else hi = mid;
    }
    out.push(va ? [a, lo] : [hi, b]);
  }
  return out;
}

/** Sky and ground illuminance (lux) at p, normal n, through one window (see the file's comment). */
export function skyThroughWindow(ctx: DaylightContext, w: DaylightWindow, p: Vec3, n: Vec3): number {
  if (!ctx.sky && !(ctx.groundLuminance > 0)) return 0;
  if (!(dot(sub(p, w.polygon[0]), w.inward) > 1e-12)) return 0; // p in (or behind) the window's plane
  const [s0, s1, t0, t1] = w.bounds;
  const diagonal = Math.hypot(s1 - s0, t1 - t0);
  const m = Math.min(32, Math.max(8, Math.ceil((12 * diagonal) / Math.max(distanceToWindow(w, p), 1e-6))));
  let e = 0;
  for (const [sa, sb] of visibleColumns(ctx, w, p, n, m)) {
    for (let j = 0; j < m; j++) {
      const ta = t0 + ((t1 - t0) * j) / m;
      const tb = t0 + ((t1 - t0) * (j + 1)) / m;
      const cell = [toWorld(w.frame, sa, ta), toWorld(w.frame, sb, ta), toWorld(w.frame, sb, tb), toWorld(w.frame, sa, tb)];
      for (const above of [true, false]) {
        const part = clipToFront(p, above ? UP : DOWN, cell);
        if (part.length < 3) continue;
        const f = frontFormFactor(p, n, part);
        if (!(f > 0)) continue;
        const d = sub(polygonCentroid(part), p);
        const len = Math.hypot(d[0], d[1], d[2]);
        const dir: Vec3 = [d[0] / len, d[1] / len, d[2] / len];
        // A piece touching the horizon plane keeps its side's luminance.
        const l = above ? (ctx.sky ? ctx.sky.luminance(dir[1] > 0 ? dir : [dir[0], 1e-9, dir[2]]) : 0) : ctx.groundLuminance;
        e += l * glazingTransmittance(w.glazing, Math.abs(dot(dir, w.inward))) * f;
      }
    }
  }
  // F is the view factor (a full hemisphere is 1): E = π L F.
  return Math.PI * e;
}

/** Where the ray from p toward the sun crosses the window's plane, in world and frame coordinates; null when it does not leave through the window. */
function sunExit(w: DaylightWindow, p: Vec3, s: Vec3): Vec3 | null {
  const sn = dot(s, w.inward);
  if (!(sn < 0)) return null; // the sun is on the room's side of the wall
  const t = dot(sub(w.polygon[0], p), w.inward) / sn;
  if (!(t > 1e-12)) return null;
  const hit: Vec3 = [p[0] + t * s[0], p[1] + t * s[1], p[2] + t * s[2]];
  const [hs, ht] = toFrame(w.frame, hit);
  const [s0, s1, t0, t1] = w.bounds;
  return hs >= s0 && hs <= s1 && ht >= t0 && ht <= t1 ? hit : null;
}

/** Sun illuminance (lux) at p, normal n, through one window. */
export function sunThroughWindow(ctx: DaylightContext, w: DaylightWindow, p: Vec3, n: Vec3): number {
  const sun = ctx.sun;
  if (!sun || !(sun.direction[1] > 0) || !(sun.normalIlluminance > 0)) return 0;
  const s = sun.direction;
  const cosReceiver = dot(n, s);
  if (!(cosReceiver > 0)) return 0;
  const hit = sunExit(w, p, s);
  if (!hit) return 0;
  if (!ctx.sight.convex && !sightClear(ctx.sight, p, n, hit, w.inward)) return 0;
  return sun.normalIlluminance * glazingTransmittance(w.glazing, Math.abs(dot(s, w.inward))) * cosReceiver;
}

/** All direct daylight at p (normal n): sky, ground and sun through every window, lux. */
export function daylightDirectAt(ctx: DaylightContext, p: Vec3, n: Vec3): number {
  let e = 0;
  for (const w of ctx.windows) e += skyThroughWindow(ctx, w, p, n) + sunThroughWindow(ctx, w, p, n);
  return e;
}

/** Signed area of a 2D polygon (shoelace). */
function signedArea(poly: readonly PlanPoint[]): number {
  let a = 0;
  for (let i = 0; i < poly.length; i++) {
    const p = poly[i];
    const q = poly[(i + 1) % poly.length];
    a += p[0] * q[1] - q[0] * p[1];
  }
  return a / 2;
}

/** A polygon clipped by a convex counterclockwise polygon (Sutherland & Hodgman, CACM 17(1), 1974). */
export function clipByConvex(subject: readonly PlanPoint[], clip: readonly PlanPoint[]): PlanPoint[] {
  let out: PlanPoint[] = [...subject];
  for (let k = 0; k < clip.length && out.length > 0; k++) {
    const a = clip[k];
    const b = clip[(k + 1) % clip.length];
    const side = (p: PlanPoint) => (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
    const input = out;
    out = [];
    for (let i = 0; i < input.length; i++) {
      const p = input[i];
      const q = input[(i + 1) % input.length];
      const hp = side(p);
      const hq = side(q);
      if (hp >= 0) out.push(p);
      if ((hp > 0 && hq < 0) || (hp < 0 && hq > 0)) {
        const t = hp / (hp - hq);
        out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
      }
    }
  }
  return out;
}

/** Share of a patch the sun reaches through a window, exactly, in a convex room (the window projected along s onto the patch's plane). */
export function sunlitShare(w: DaylightWindow, patch: RoomPatch, s: Vec3): number {
  const sn = dot(s, patch.normal);
  if (!(sn > 0) || !(dot(s, w.inward) < 0)) return 0;
  const c = patch.vertices[0];
  const projected: PlanPoint[] = [];
  for (const q of w.polygon) {
    const t = dot(sub(q, c), patch.normal) / sn;
    if (!(t > 1e-12)) return 0; // the window is not in front of the patch's plane
    projected.push(toFrame(patch.frame, [q[0] - t * s[0], q[1] - t * s[1], q[2] - t * s[2]]));
  }
  if (signedArea(projected) < 0) projected.reverse();
  const lit = clipByConvex(patch.polygon2d, projected);
  return lit.length < 3 ? 0 : Math.abs(signedArea(lit)) / Math.abs(signedArea(patch.polygon2d));
}

/** Pieces per side for a patch's mean sky light: finer near a window, within [2, 8]. */
function skyPiecesPerSide(ctx: DaylightContext, patch: RoomPatch): number {
  let near = Infinity;
  for (const w of ctx.windows) near = Math.min(near, distanceToWindow(w, patch.centroid));
  return Math.min(8, Math.max(2, Math.ceil((4 * patch.diameter) / Math.max(near, 1e-6))));
}

/**
 * Mean direct daylight over a patch (lux): the sky and ground by the area-weighted midpoint rule
 * on its pieces; the sun exactly (sunlitShare) in a convex room, else on 16 × 16 pieces.
 */
export function patchMeanDaylight(ctx: DaylightContext, patch: RoomPatch): { sky: number; sun: number } {
  let sky = 0;
  if (ctx.windows.length > 0 && (ctx.sky || ctx.groundLuminance > 0)) {
    for (const piece of patchPieces(patch, skyPiecesPerSide(ctx, patch))) {
      let e = 0;
      for (const w of ctx.windows) e += skyThroughWindow(ctx, w, piece.centroid, patch.normal);
      sky += (e * piece.area) / patch.area;
    }
  }
  let sun = 0;
  const s = ctx.sun;
  if (s && s.direction[1] > 0 && s.normalIlluminance > 0 && dot(s.direction, patch.normal) > 0) {
    if (ctx.sight.convex) {
      for (const w of ctx.windows) {
        const share = sunlitShare(w, patch, s.direction);
        if (share > 0) sun += share * s.normalIlluminance * glazingTransmittance(w.glazing, Math.abs(dot(s.direction, w.inward))) * dot(s.direction, patch.normal);
      }
    } else {
      for (const piece of patchPieces(patch, 16)) {
        let e = 0;
        for (const w of ctx.windows) e += sunThroughWindow(ctx, w, piece.centroid, patch.normal);
        sun += (e * piece.area) / patch.area;
      }
    }
  }
  return { sky, sun };
}

/** 4-point Gauss–Legendre on [−1, 1] (Abramowitz & Stegun 25.4.30). */
const GAUSS4 = [
  [-0.8611363115940526, 0.3478548451374538],
  [-0.3399810435848563, 0.6521451548625461],
  [0.3399810435848563, 0.6521451548625461],
  [0.8611363115940526, 0.3478548451374538],
] as const;

/**
 * Illuminance (lux) that the sky and the ground give the outer face of a vertical window,
 * transmitted: E = ∫ L(d)·τ(θ)·cos θ dω over the outward hemisphere, unobstructed, in the
 * window's own angles (elevation α, azimuth β from the outward normal, dω = cos α dα dβ):
 * composite 4-point Gauss–Legendre on 24 pieces of each of [−90°, 0] (ground) and [0, 90°] (sky)
 * and 48 of β ∈ [−90°, 90°]. Times the window's area, the light entering through it: the flux
 * balance's left side, independent of the room's patches.
 */
export function transmittedSkyOnWindow(ctx: DaylightContext, w: DaylightWindow): number {
  const out: Vec3 = [-w.inward[0], -w.inward[1], -w.inward[2]];
  if (Math.abs(out[1]) > 1e-9) throw new RangeError('transmittedSkyOnWindow: windows stand in vertical walls');
  const tangent: Vec3 = [out[2], 0, -out[0]];
  let e = 0;
  const nA = 24;
  const nB = 48;
  for (const [lo, hi] of [
    [-Math.PI / 2, 0],
    [0, Math.PI / 2],
  ]) {
    for (let i = 0; i < nA; i++) {
      const a0 = lo + ((hi - lo) * i) / nA;
      const ha = (hi - lo) / nA / 2;
      for (const [xa, wa] of GAUSS4) {
        const alpha = a0 + ha * (xa + 1);
        const ca = Math.cos(alpha);
        const sa = Math.sin(alpha);
        for (let j = 0; j < nB; j++) {
          const hb = Math.PI / nB / 2;
          const b0 = -Math.PI / 2 + (Math.PI * j) / nB;
          for (const [xb, wb] of GAUSS4) {
            const beta = b0 + hb * (xb + 1);
            const cosTheta = ca * Math.cos(beta);
            const d: Vec3 = [cosTheta * out[0] + ca * Math.sin(beta) * tangent[0], sa, cosTheta * out[2] + ca * Math.sin(beta) * tangent[2]];
            const l = alpha > 0 ? (ctx.sky ? ctx.sky.luminance(d) : 0) : ctx.groundLuminance;
            e += wa * ha * wb * hb * l * glazingTransmittance(w.glazing, cosTheta) * cosTheta * ca;
          }
        }
      }
    }
  }
  return e;
}

/** Illuminance the sun gives the window's outer face, transmitted (lux): E_n·τ(θ)·cos θ. */
export function transmittedSunOnWindow(ctx: DaylightContext, w: DaylightWindow): number {
  const sun = ctx.sun;
  if (!sun || !(sun.direction[1] > 0)) return 0;
  const c = -dot(sun.direction, w.inward);
  return c > 0 ? sun.normalIlluminance * glazingTransmittance(w.glazing, c) * c : 0;
}
