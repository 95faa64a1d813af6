import { SURFACE_NAMES, type LightingScene, type Reflectance, type Rgb, type SurfaceName, type Vec3 } from '../core/model/lightingScene/lightingScene';
import type { Photometry } from '../core/photometry/types';
import { BOX_FACES, makePatchGrid, type Axis, type BoxFace, type PatchGrid } from './boxGeometry';
import { patchMeanDirect, type PatchAverageOptions } from './directIlluminance';
import { buildFaceKernels, type FaceKernel } from './formFactorKernels';
import { referencePointSources, type PointSourceOptions, type ReferencePointSource } from './pointSources';
import { ReferenceInputError } from './referenceInputError';

/** Rec. 709 / sRGB luminance weights: Y of linear RGB illuminance (IEC 61966-2-1). */
export const LUMINANCE_WEIGHTS: Rgb = [0.2126, 0.7152, 0.0722];

export interface ReferenceOptions extends PointSourceOptions {
  /** Patch edge length in metres (each axis is divided into ⌈extent/patchSize⌉ equal parts). */
  patchSize?: number;
  /** When patchSize is absent: aim for about this many patches in all (default 3000). */
  targetPatches?: number;
  /** Stop when the largest change of indirect illuminance in a sweep is below tolerance × the largest total (default 1e-6). */
  tolerance?: number;
  /** Give up (with an error) after this many Gauss–Seidel sweeps (default 20 000). */
  maxSweeps?: number;
  /** Relative tolerance of the adaptive patch quadrature of direct light (default 1e-3; absolute floor 1e-4 of the mean direct illuminance). */
  directRelTol?: number;
}

export const DEFAULT_TARGET_PATCHES = 3000;
/** Above this the O(N²) sweeps get too slow for a reference run; ask for a coarser patch size. */
export const MAX_PATCHES = 40_000;

export interface ReferenceSurface {
  name: SurfaceName;
  /** Which world axes u and v run along, 0 = x, 1 = y, 2 = z (see boxGeometry.ts). */
  uAxis: Axis;
  vAxis: Axis;
  /** Patch counts and sizes (metres) along u and v; patch (iu, iv) is at index iv·nu + iu. */
  nu: number;
  nv: number;
  du: number;
  dv: number;
  /** Face area, m². */
  area: number;
  reflectance: Rgb;
  /** Patch-mean illuminance, lux, luminance-weighted (Y) — equals every channel for white light on grey walls. */
  direct: Float64Array;
  indirect: Float64Array;
  total: Float64Array;
  /** The same per linear RGB channel, interleaved [r, g, b, r, g, b, …]. */
  directRgb: Float64Array;
  indirectRgb: Float64Array;
  totalRgb: Float64Array;
}

export interface ReferenceResult {
  scene: LightingScene;
  sources: ReferencePointSource[];
  grid: PatchGrid;
  surfaces: Record<SurfaceName, ReferenceSurface>;
  patches: number;
  /** Gauss–Seidel sweeps run and the final relative change (see ReferenceOptions.tolerance). */
  sweeps: number;
  residual: number;
  timingsMs: { direct: number; formFactors: number; solve: number };
}

function toRgb(r: Reflectance, where: string): Rgb {
  const rgb: Rgb = typeof r === 'number' ? [r, r, r] : Array.isArray(r) && r.length === 3 ? [r[0], r[1], r[2]] : [NaN, NaN, NaN];
  if (!rgb.every((c) => Number.isFinite(c) && c >= 0 && c < 1)) {
    throw new ReferenceInputError(`${where}: reflectance must be a number or [r, g, b], each in [0, 1)`);
  }
  return rgb;
}

function validateRoom(scene: LightingScene): Vec3 {
  if (typeof scene?.room !== 'object' || scene.room === null) throw new ReferenceInputError('room: expected an object with width, height, depth and reflectance');
  const { width, height, depth } = scene.room;
  const extent: Vec3 = [width, height, depth];
  (['width', 'height', 'depth'] as const).forEach((k, a) => {
    if (!Number.isFinite(extent[a]) || extent[a] <= 0) throw new ReferenceInputError(`room.${k}: expected a finite length > 0 m, got ${extent[a]}`);
  });
  return extent;
}

function choosePatchSize(extent: Vec3, options: ReferenceOptions): number {
  if (options.patchSize !== undefined) {
    if (!Number.isFinite(options.patchSize) || options.patchSize <= 0) {
      throw new ReferenceInputError(`reference options: patchSize must be a finite length > 0 m, got ${options.patchSize}`);
    }
    return options.patchSize;
  }
  const target = options.targetPatches ?? DEFAULT_TARGET_PATCHES;
  if (!Number.isFinite(target) || target < 6) throw new ReferenceInputError(`reference options: targetPatches must be ≥ 6, got ${target}`);
  const [w, h, d] = extent;
  return Math.sqrt((2 * (w * h + w * d + h * d)) / target);
}

/**
 * Flux of a candela grid, lm, by the midpoint rule over its cells: only a scale
 * for quadrature tolerances (the tests compare against src/core/photometry's exact
 * integral instead).
 */
function gridFlux(ph: Photometry): number {
  const va = ph.verticalAngles;
  const ha = ph.horizontalAngles;
  const d = Math.PI / 180;
  let flux = 0;
  for (let h = 0; h < Math.max(1, ha.length - 1); h++) {
    const dc = ha.length === 1 ? 2 * Math.PI : (ha[h + 1] - ha[h]) * d;
    const r0 = ph.candela[h];
    const r1 = ph.candela[ha.length === 1 ? h : h + 1];
    for (let v = 0; v + 1 < va.length; v++) {
      const mean = 0.25 * (r0[v] + r0[v + 1] + r1[v] + r1[v + 1]);
      flux += mean * (Math.cos(va[v] * d) - Math.cos(va[v + 1] * d)) * dc;
    }
  }
  return flux;
}

/**
 * Largest angle a quadrature cell may subtend: four times the typical (median)
 * vertical step of the photometries in use, within [0.5°, 8°] (the 3×3 rule then
 * has a node at least every ~1.5 steps). The median, not
 * the minimum: parsers append a zero row a hair beyond a 0–90° grid, and that
 * sliver must not drive the refinement everywhere.
 */
function maxCellAngle(sources: readonly ReferencePointSource[]): number {
  let step = 2;
  for (const ph of new Set(sources.map((x) => x.photometry))) {
    const va = ph.verticalAngles;
    const steps = va
      .slice(1)
      .map((v, i) => v - va[i])
      .sort((a, b) => a - b);
    if (steps.length > 0) step = Math.min(step, steps[steps.length >> 1]);
  }
  return (Math.min(Math.max(4 * step, 0.5), 8) * Math.PI) / 180;
}

/**
 * Converged diffuse interreflection in an empty box room, by piecewise-constant
 * radiosity (Goral, Torrance, Greenberg & Battaile, SIGGRAPH 1984) with exact
 * patch-to-patch form factors and Gauss–Seidel sweeps:
 *
 *   E_ind,i = Σ_j F_ij · ρ_j (E_dir,j + E_ind,j)      per RGB channel,
 *
 * where E_dir,i is the patch mean of the point-source direct illuminance (adaptive
 * quadrature). Shares no code with src/engines/bake or the shaders, by design.
 */
export function solveBoxReference(scene: LightingScene, photometries: ReadonlyMap<string, Photometry> | Record<string, Photometry>, options: ReferenceOptions = {}): ReferenceResult {
  const { extent, reflectance, tolerance, maxSweeps, relTol } = checkedBoxInput(scene, options);
  const sources = referencePointSources(scene, photometries, options);
  const grid = makePatchGrid(extent, choosePatchSize(extent, options));
  const faceN = BOX_FACES.map((f) => grid.count[f.uAxis] * grid.count[f.vAxis]);
  const patches = faceN.reduce((a, b) => a + b, 0);
  if (patches > MAX_PATCHES) {
    throw new ReferenceInputError(`reference options: ${patches} patches exceed the limit of ${MAX_PATCHES}; choose a larger patchSize`);
  }

  let t0 = performance.now();
  const direct = boxDirect(sources, extent, grid, faceN, relTol);
  const directMs = performance.now() - t0;

  // Indirect light.
  t0 = performance.now();
  const anyReflective = SURFACE_NAMES.some((n) => reflectance[n].some((c) => c > 0));
  const kernels = anyReflective ? buildFaceKernels(grid) : [];
  const formFactorMs = performance.now() - t0;
  t0 = performance.now();
  const indirect = BOX_FACES.map((_, fi) => new Float64Array(3 * faceN[fi]));
  let sweeps = 0;
  let residual = 0;
  if (anyReflective) {
    ({ sweeps, residual } = gaussSeidel(
      grid,
      kernels,
      direct,
      indirect,
      BOX_FACES.map((f) => reflectance[f.name]),
      tolerance,
      maxSweeps,
    ));
  }
  const solveMs = performance.now() - t0;
  const surfaces = boxSurfaces(extent, grid, reflectance, direct, indirect);
  return { scene, sources, grid, surfaces, patches, sweeps, residual, timingsMs: { direct: directMs, formFactors: formFactorMs, solve: solveMs } };
}

/** The room, its reflectances and the solver options, each checked with a message naming the field. */
function checkedBoxInput(scene: LightingScene, options: ReferenceOptions) {
  const extent = validateRoom(scene);
  if (typeof scene.room.reflectance !== 'object' || scene.room.reflectance === null) throw new ReferenceInputError('room.reflectance: expected an object with one entry per surface');
  const reflectance = {} as Record<SurfaceName, Rgb>;
  for (const name of SURFACE_NAMES) reflectance[name] = toRgb(scene.room.reflectance[name], `room.reflectance.${name}`);
  if (!Array.isArray(scene.luminaires)) throw new ReferenceInputError('luminaires: expected an array');
  const tolerance = options.tolerance ?? 1e-6;
  const maxSweeps = options.maxSweeps ?? 20_000;
  if (!(tolerance > 0 && tolerance < 1)) throw new ReferenceInputError(`reference options: tolerance must be in (0, 1), got ${tolerance}`);
  if (!Number.isInteger(maxSweeps) || maxSweeps < 1) throw new ReferenceInputError(`reference options: maxSweeps must be an integer ≥ 1, got ${maxSweeps}`);
  const relTol = options.directRelTol ?? 1e-3;
  if (!(relTol > 0 && relTol < 1)) throw new ReferenceInputError(`reference options: directRelTol must be in (0, 1), got ${relTol}`);
  return { extent, reflectance, tolerance, maxSweeps, relTol };
}

/**
 * Direct light: patch means, RGB per patch per face. Quadrature errors are judged against the
 * room's mean direct illuminance Φ/S, so dark patches are not refined for nothing.
 */
function boxDirect(sources: ReturnType<typeof referencePointSources>, extent: ReturnType<typeof validateRoom>, grid: ReturnType<typeof makePatchGrid>, faceN: number[], relTol: number): Float64Array[] {
  const area = 2 * (extent[0] * extent[1] + extent[0] * extent[2] + extent[1] * extent[2]);
  const meanDirect = sources.reduce((sum, s) => sum + gridFlux(s.photometry) * Math.max(...s.scale), 0) / area;
  const quadrature: PatchAverageOptions = {
    relTol,
    absTol: 1e-4 * meanDirect,
    maxDepth: 6,
    maxCellAngle: maxCellAngle(sources),
  };
  return BOX_FACES.map((f, fi) => {
    const out = new Float64Array(3 * faceN[fi]);
    if (sources.length === 0) return out;
    const nu = grid.count[f.uAxis];
    const hu = grid.size[f.uAxis];
    const hv = grid.size[f.vAxis];
    const rect = { axis: f.axis, plane: f.side === 0 ? 0 : extent[f.axis], uAxis: f.uAxis, vAxis: f.vAxis, normal: f.normal };
    for (let i = 0; i < faceN[fi]; i++) {
      const iu = i % nu;
      const iv = (i - iu) / nu;
      const e = patchMeanDirect(sources, rect, iu * hu, (iu + 1) * hu, iv * hv, (iv + 1) * hv, quadrature);
      out.set(e, 3 * i);
    }
    return out;
  });
}

/** Each face's patches as the result reports them: direct, indirect and total, in RGB and as luminance-weighted lux. */
function boxSurfaces(extent: ReturnType<typeof validateRoom>, grid: ReturnType<typeof makePatchGrid>, reflectance: Record<SurfaceName, Rgb>, direct: Float64Array[], indirect: Float64Array[]) {
  const surfaces = {} as Record<SurfaceName, ReferenceSurface>;
  BOX_FACES.forEach((f, fi) => {
    const n = direct[fi].length / 3;
    const totalRgb = new Float64Array(3 * n);
    const y = (rgb: Float64Array): Float64Array => {
      const out = new Float64Array(n);
      for (let i = 0; i < n; i++) {
        out[i] = LUMINANCE_WEIGHTS[0] * rgb[3 * i] + LUMINANCE_WEIGHTS[1] * rgb[3 * i + 1] + LUMINANCE_WEIGHTS[2] * rgb[3 * i + 2];
      }
      return out;
    };
    for (let k = 0; k < 3 * n; k++) totalRgb[k] = direct[fi][k] + indirect[fi][k];
    surfaces[f.name] = {
      name: f.name,
      uAxis: f.uAxis,
      vAxis: f.vAxis,
      nu: grid.count[f.uAxis],
      nv: grid.count[f.vAxis],
      du: grid.size[f.uAxis],
      dv: grid.size[f.vAxis],
      area: extent[f.uAxis] * extent[f.vAxis],
      reflectance: reflectance[f.name],
      direct: y(direct[fi]),
      indirect: y(indirect[fi]),
      total: y(totalRgb),
      directRgb: direct[fi],
      indirectRgb: indirect[fi],
      totalRgb,
    };
  });
  return surfaces;
}

/**
 * Gauss–Seidel sweeps over all patches (each update uses the newest neighbours),
 * in place on `indirect`. Returns the sweeps run and the final relative change.
 */
function gaussSeidel(grid: PatchGrid, kernels: (FaceKernel | null)[], direct: Float64Array[], indirect: Float64Array[], rho: Rgb[], tolerance: number, maxSweeps: number): { sweeps: number; residual: number } {
  const faces = BOX_FACES;
  // Exitance M = ρ(E_dir + E_ind) per face, RGB interleaved, kept in step with `indirect`.
  const exitance = faces.map((_, fi) => {
    const m = new Float64Array(direct[fi].length);
    for (let k = 0; k < m.length; k++) m[k] = rho[fi][k % 3] * direct[fi][k];
    return m;
  });
  // For each perpendicular pair, Q's patches listed as [ja][js] (distance from the
  // common edge, then position along the shared axis) so the inner loop runs
  // along a contiguous kernel row.
  const order: (Int32Array | null)[] = [];
  for (let p = 0; p < 6; p++) {
    for (let q = 0; q < 6; q++) {
      const k = kernels[p * 6 + q];
      order.push(k && k.kind === 'perpendicular' ? perpendicularOrder(grid, faces[p], faces[q]) : null);
    }
  }
  let maxTotal = 0;
  for (let fi = 0; fi < 6; fi++) for (const v of direct[fi]) maxTotal = Math.max(maxTotal, v);
  if (!(maxTotal > 0)) return { sweeps: 0, residual: 0 };
  const idx: [number, number, number] = [0, 0, 0];
  const g = new Float64Array(3);
  let residual = Infinity;
  let sweeps = 0;
  while (residual > tolerance) {
    if (sweeps >= maxSweeps) {
      throw new ReferenceInputError(`reference solver: no convergence after ${maxSweeps} sweeps (relative change ${residual.toExponential(2)}); raise maxSweeps`);
    }
    sweeps++;
    let change = 0;
    for (let p = 0; p < 6; p++) {
      const P = faces[p];
      const nu = grid.count[P.uAxis];
      const nP = direct[p].length / 3;
      const rP = rho[p];
      for (let i = 0; i < nP; i++) {
        const iu = i % nu;
        idx[P.uAxis] = iu;
        idx[P.vAxis] = (i - iu) / nu;
        g[0] = 0;
        g[1] = 0;
        g[2] = 0;
        for (let q = 0; q < 6; q++) {
          const k = kernels[p * 6 + q];
          if (!k) continue;
          if (k.kind === 'parallel') gatherParallel(k, idx[P.uAxis], idx[P.vAxis], exitance[q], g);
          else gatherPerpendicular(k, P, faces[q], idx, order[p * 6 + q] as Int32Array, exitance[q], g);
        }
        const e = indirect[p];
        const m = exitance[p];
        const d = direct[p];
        for (let c = 0; c < 3; c++) {
          const j = 3 * i + c;
          change = Math.max(change, Math.abs(g[c] - e[j]));
          e[j] = g[c];
          m[j] = rP[c] * (d[j] + g[c]);
          maxTotal = Math.max(maxTotal, d[j] + g[c]);
        }
      }
    }
    residual = change / maxTotal;
  }
  return { sweeps, residual };
}

function gatherParallel(k: { nu: number; nv: number; factor: Float64Array }, iu: number, iv: number, m: Float64Array, g: Float64Array): void {
  const { nu, nv, factor } = k;
  const wu = 2 * nu - 1;
  let r = 0;
  let gr = 0;
  let gg = 0;
  let gb = 0;
  for (let jv = 0; jv < nv; jv++) {
    const row = (jv - iv + nv - 1) * wu + nu - 1 - iu;
    for (let ju = 0; ju < nu; ju++, r += 3) {
      const f = factor[row + ju];
      gr += f * m[r];
      gg += f * m[r + 1];
      gb += f * m[r + 2];
    }
  }
  g[0] += gr;
  g[1] += gg;
  g[2] += gb;
}

function gatherPerpendicular(k: { ns: number; nb: number; na: number; factor: Float64Array }, P: BoxFace, Q: BoxFace, idx: [number, number, number], order: Int32Array, m: Float64Array, g: Float64Array): void {
  const { ns, nb, na, factor } = k;
  const s = 3 - P.axis - Q.axis;
  const is = idx[s];
  const kb = idx[Q.axis];
  const ib = Q.side === 0 ? kb : nb - 1 - kb;
  const ws = 2 * ns - 1;
  let gr = 0;
  let gg = 0;
  let gb = 0;
  let o = 0;
  for (let ja = 0; ja < na; ja++) {
    const row = (ib * na + ja) * ws + ns - 1 - is;
    for (let js = 0; js < ns; js++, o++) {
      const f = factor[row + js];
      const j = 3 * order[o];
      gr += f * m[j];
      gg += f * m[j + 1];
      gb += f * m[j + 2];
    }
  }
  g[0] += gr;
  g[1] += gg;
  g[2] += gb;
}

/** Q's patch indices ordered [ja][js] for the pair (P, Q) of perpendicular faces. */
function perpendicularOrder(grid: PatchGrid, P: BoxFace, Q: BoxFace): Int32Array {
  const s = 3 - P.axis - Q.axis;
  const ns = grid.count[s];
  const na = grid.count[P.axis];
  const nu = grid.count[Q.uAxis];
  const out = new Int32Array(ns * na);
  const idx = [0, 0, 0];
  for (let ja = 0; ja < na; ja++) {
    idx[P.axis] = P.side === 0 ? ja : na - 1 - ja;
    for (let js = 0; js < ns; js++) {
      idx[s] = js;
      out[ja * ns + js] = idx[Q.vAxis] * nu + idx[Q.uAxis];
    }
  }
  return out;
}
