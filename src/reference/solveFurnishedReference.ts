import { SURFACE_NAMES, type LightingScene, type Reflectance, type Rgb, type SurfaceName, type Vec3 } from '../core/model/lightingScene/lightingScene';
import type { Photometry } from '../core/photometry/types';
import { objectPatches, wallPatches, type FurnishedPatch } from './furnishedPatches';
import { occludedFormFactor, polygonCentroid, splitPolygon } from './occludedFormFactor';
import { patchMeanOccludedDirect } from './occludedDirect';
import { mayOcclude, segmentClear, type Occluders } from './occluders';
import { referencePointSources, type PointSourceOptions, type ReferencePointSource } from './pointSources';
import { placeReferenceObjects, type PlacedTriangles, type ReferenceObject } from './referenceObjects';
import { ReferenceInputError } from './referenceInputError';
import { LUMINANCE_WEIGHTS } from './solveBoxReference';
import { buildTriangleBvh } from './triangleBvh';

export interface FurnishedOptions extends PointSourceOptions {
  /** Edge of the wall patches, metres (each axis in ⌈extent/patchSize⌉ equal parts; default 0.25). */
  patchSize?: number;
  /** Longest edge of the object patches (mesh triangles cut by longest-edge bisection), metres (default patchSize). */
  objectPatchSize?: number;
  /** Stop when the largest change of indirect illuminance in a sweep is below tolerance × the largest total (default 1e-6). */
  tolerance?: number;
  /** Give up (with an error) after this many Gauss–Seidel sweeps (default 10 000). */
  maxSweeps?: number;
}

/** The dense form-factor matrix is N² numbers: keep it within a few hundred MB. */
export const MAX_FURNISHED_PATCHES = 8000;

/** A receiver patch larger than this fraction of the distance to the emitter averages over 16 points of itself, … */
const NEAR_RECEIVER = 0.6;
/** … larger than this fraction over 4 points, else its centre alone (point-to-patch error ~ (size/distance)²). */
const MID_RECEIVER = 0.3;
/**
 * An emitter smaller than this fraction of its distance gets one centre-to-centre shadow
 * ray in the matrix (visibility at patch resolution); larger ones get the adaptive rays of
 * occludedFormFactor. Query points always get the adaptive rays.
 */
const SMALL_ANGLE = 0.5;

export interface FurnishedResult {
  extent: Vec3;
  sources: ReferencePointSource[];
  placed: PlacedTriangles;
  occluders: Occluders | null;
  patches: FurnishedPatch[];
  wallPatchCount: number;
  /** Patch-mean illuminance per patch, lux, RGB interleaved (3 per patch). */
  directRgb: Float64Array;
  indirectRgb: Float64Array;
  /** Exitance M = ρ·(E_dir + E_ind) per patch, lm/m², RGB interleaved. */
  exitanceRgb: Float64Array;
  /** Gauss–Seidel sweeps and the final relative change (tolerance). */
  sweeps: number;
  residual: number;
  timingsMs: { direct: number; formFactors: number; solve: number };
}

function rgbOf(r: Reflectance, where: string): Rgb {
  const rgb: Rgb = typeof r === 'number' ? [r, r, r] : Array.isArray(r) && r.length === 3 ? [r[0], r[1], r[2]] : [NaN, NaN, NaN];
  if (!rgb.every((c) => Number.isFinite(c) && c >= 0 && c < 1)) throw new ReferenceInputError(`${where}: reflectance must be a number or [r, g, b], each in [0, 1)`);
  return rgb;
}

/** Y (luminance-weighted lux) of an RGB triple at offset k. */
export function luminanceAt(rgb: ArrayLike<number>, k: number): number {
  return LUMINANCE_WEIGHTS[0] * rgb[k] + LUMINANCE_WEIGHTS[1] * rgb[k + 1] + LUMINANCE_WEIGHTS[2] * rgb[k + 2];
}

/** Receiver points of a patch: the centres of its 4^levels similar pieces. */
function receiverPoints(p: FurnishedPatch, levels: number): Vec3[] {
  let pieces: Vec3[][] = [p.vertices];
  for (let level = 0; level < levels; level++) pieces = pieces.flatMap((q) => splitPolygon(q));
  return pieces.map(polygonCentroid);
}

/**
 * Converged diffuse interreflection in a box room with triangle-mesh objects, by
 * piecewise-constant radiosity (Goral et al., SIGGRAPH 1984) on wall rectangles and
 * subdivided object triangles:
 *
 *   E_ind,i = Σ_j F_ij · ρ_j (E_dir,j + E_ind,j)      per RGB channel,
 *
 * with F_re the point-to-polygon form factor (Lambert's contour integral, exact for the
 * unoccluded part) from the centre of the smaller patch r of each pair — the mean over 4
 * or 16 points of r when r looks large from e — times the visibility found by shadow rays
 * through the reference's own BVH (occludedFormFactor.ts), and F_er = F_re·A_r/A_e by
 * reciprocity. E_dir is the patch mean of occluded point-source light. Gauss–Seidel sweeps
 * run until the largest change is below `tolerance` × the largest total. Shares no code
 * with src/engines/bake, the shaders or three-mesh-bvh.
 */
export function solveFurnishedReference(scene: LightingScene, photometries: ReadonlyMap<string, Photometry> | Record<string, Photometry>, objects: readonly ReferenceObject[], options: FurnishedOptions = {}): FurnishedResult {
  if (typeof scene?.room !== 'object' || scene.room === null) throw new ReferenceInputError('room: expected an object with width, height, depth and reflectance');
  const { width, height, depth } = scene.room;
  const extent: Vec3 = [width, height, depth];
  (['width', 'height', 'depth'] as const).forEach((k, a) => {
    if (!Number.isFinite(extent[a]) || extent[a] <= 0) throw new ReferenceInputError(`room.${k}: expected a finite length > 0 m, got ${extent[a]}`);
  });
  if (typeof scene.room.reflectance !== 'object' || scene.room.reflectance === null) throw new ReferenceInputError('room.reflectance: expected an object with one entry per surface');
  const reflectance = {} as Record<SurfaceName, Rgb>;
  for (const name of SURFACE_NAMES) reflectance[name] = rgbOf(scene.room.reflectance[name], `room.reflectance.${name}`);
  if (!Array.isArray(scene.luminaires)) throw new ReferenceInputError('luminaires: expected an array');
  const patchSize = options.patchSize ?? 0.25;
  if (!(Number.isFinite(patchSize) && patchSize > 0)) throw new ReferenceInputError(`reference options: patchSize must be a finite length > 0 m, got ${patchSize}`);
  const objectPatchSize = options.objectPatchSize ?? patchSize;
  if (!(Number.isFinite(objectPatchSize) && objectPatchSize > 0)) throw new ReferenceInputError(`reference options: objectPatchSize must be a finite length > 0 m, got ${objectPatchSize}`);
  const tolerance = options.tolerance ?? 1e-6;
  if (!(tolerance > 0 && tolerance < 1)) throw new ReferenceInputError(`reference options: tolerance must be in (0, 1), got ${tolerance}`);
  const maxSweeps = options.maxSweeps ?? 10_000;
  if (!Number.isInteger(maxSweeps) || maxSweeps < 1) throw new ReferenceInputError(`reference options: maxSweeps must be an integer ≥ 1, got ${maxSweeps}`);

  const sources = referencePointSources(scene, photometries, options);
  const placed = placeReferenceObjects(objects, extent);
  const occluders: Occluders | null = placed.count > 0 ? { bvh: buildTriangleBvh(placed.corners), objectBounds: placed.objectBounds } : null;
  const walls = wallPatches(extent, patchSize, reflectance);
  const patches = [...walls, ...objectPatches(placed, objectPatchSize)];
  const N = patches.length;
  if (N > MAX_FURNISHED_PATCHES) {
    throw new ReferenceInputError(`reference options: ${N} patches exceed the limit of ${MAX_FURNISHED_PATCHES}; choose a larger patchSize or objectPatchSize`);
  }

  let t0 = performance.now();
  const directRgb = new Float64Array(3 * N);
  patches.forEach((p, i) => directRgb.set(patchMeanOccludedDirect(sources, occluders, p), 3 * i));
  const directMs = performance.now() - t0;

  // Form factors, row i = what patch i sees. Float32 halves the memory; 1e-7 relative is far below the method's error.
  t0 = performance.now();
  const anyReflective = patches.some((p) => p.reflectance.some((c) => c > 0));
  const F = anyReflective ? new Float32Array(N * N) : new Float32Array(0);
  if (anyReflective) {
    const far = { minDepth: 0, maxDepth: 2 };
    const levels = patches.map(() => [] as Vec3[][]);
    const pointsOf = (k: number, level: number): Vec3[] => (levels[k][level] ??= receiverPoints(patches[k], level));
    const reflective = patches.map((p) => p.reflectance.some((c) => c > 0));
    for (let i = 0; i < N; i++) {
      for (let j = i + 1; j < N; j++) {
        if (!reflective[i] && !reflective[j]) continue;
        // Integrate over the smaller patch (points) against the larger (exact polygon); the
        // other direction follows by reciprocity, A_i·F_ij = A_j·F_ji, which the discrete
        // system then keeps exactly.
        const [r, e] = patches[j].diameter < patches[i].diameter ? [j, i] : [i, j];
        const R = patches[r];
        const E = patches[e];
        const gap = Math.hypot(R.centroid[0] - E.centroid[0], R.centroid[1] - E.centroid[1], R.centroid[2] - E.centroid[2]);
        let f = 0;
        const level = R.diameter > NEAR_RECEIVER * gap ? 2 : R.diameter > MID_RECEIVER * gap ? 1 : 0;
        if (level > 0) {
          const points = pointsOf(r, level);
          for (const x of points) f += occludedFormFactor(x, R.normal, E.vertices, E.normal, occluders, far);
          f /= points.length;
        } else if (!occluders || E.diameter > SMALL_ANGLE * gap) {
          f = occludedFormFactor(R.centroid, R.normal, E.vertices, E.normal, occluders, far);
        } else {
          f = occludedFormFactor(R.centroid, R.normal, E.vertices, E.normal, null, far);
          if (f > 0 && occluders && mayOcclude(occluders, R.centroid, E.bounds) && !segmentClear(occluders, R.centroid, R.normal, E.centroid, E.normal)) f = 0;
        }
        F[r * N + e] = f;
        F[e * N + r] = (f * R.area) / E.area;
      }
    }
  }
  const formFactorMs = performance.now() - t0;

  t0 = performance.now();
  const indirectRgb = new Float64Array(3 * N);
  const exitanceRgb = new Float64Array(3 * N);
  for (let i = 0; i < N; i++) for (let c = 0; c < 3; c++) exitanceRgb[3 * i + c] = patches[i].reflectance[c] * directRgb[3 * i + c];
  let sweeps = 0;
  let residual = 0;
  let maxTotal = 0;
  for (const v of directRgb) maxTotal = Math.max(maxTotal, v);
  if (anyReflective && maxTotal > 0) {
    residual = Infinity;
    while (residual > tolerance) {
      if (sweeps >= maxSweeps) {
        throw new ReferenceInputError(`furnished reference: no convergence after ${maxSweeps} sweeps (relative change ${residual.toExponential(2)}); raise maxSweeps`);
      }
      sweeps++;
      let change = 0;
      for (let i = 0; i < N; i++) {
        let r = 0;
        let g = 0;
        let b = 0;
        const row = i * N;
        for (let j = 0; j < N; j++) {
          const f = F[row + j];
          if (f === 0) continue;
          r += f * exitanceRgb[3 * j];
          g += f * exitanceRgb[3 * j + 1];
          b += f * exitanceRgb[3 * j + 2];
        }
        const rho = patches[i].reflectance;
        const gathered = [r, g, b];
        for (let c = 0; c < 3; c++) {
          const k = 3 * i + c;
          change = Math.max(change, Math.abs(gathered[c] - indirectRgb[k]));
          indirectRgb[k] = gathered[c];
          exitanceRgb[k] = rho[c] * (directRgb[k] + gathered[c]);
          maxTotal = Math.max(maxTotal, directRgb[k] + gathered[c]);
        }
      }
      residual = change / maxTotal;
    }
  }
  const solveMs = performance.now() - t0;
  return {
    extent,
    sources,
    placed,
    occluders,
    patches,
    wallPatchCount: walls.length,
    directRgb,
    indirectRgb,
    exitanceRgb,
    sweeps,
    residual,
    timingsMs: { direct: directMs, formFactors: formFactorMs, solve: solveMs },
  };
}
