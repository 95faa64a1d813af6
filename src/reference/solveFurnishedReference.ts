import { SURFACE_NAMES, type LightingScene, type Reflectance, type Rgb, type SurfaceName, type Vec3 } from '../core/model/lightingScene/lightingScene';
import type { Photometry } from '../core/photometry/types';
import { objectPatches, wallPatches, type FurnishedPatch } from './furnishedPatches';
import { occludedFormFactor, polygonCentroid, splitPolygon } from './occludedFormFactor';
import { patchMeanOccludedDirect } from './occludedDirect';
import { mayOcclude, segmentClear, type Occluders } from './occluders';
import { referencePointSources, type PointSourceOptions, type ReferencePointSource } from './pointSources';
import { placeReferenceObjects, type PlacedTriangles, type ReferenceObject } from './referenceObjects';
import { gaussSeidelRadiosity } from './gaussSeidelRadiosity';
import { pairFormFactors } from './pairFormFactors';
import { referenceSolverOptions, type ReferenceSolverOptions } from './referenceSolverOptions';
import { ReferenceInputError } from './referenceInputError';
import { LUMINANCE_WEIGHTS } from './solveBoxReference';
import { buildTriangleBvh } from './triangleBvh';

export interface FurnishedOptions extends PointSourceOptions, ReferenceSolverOptions {
  /** Longest edge of the object patches (mesh triangles cut by longest-edge bisection), metres (default patchSize: the walls' in each axis in ⌈extent/patchSize⌉ equal parts). */
  objectPatchSize?: number;
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
  const { patchSize, tolerance, maxSweeps } = referenceSolverOptions(options);
  const objectPatchSize = options.objectPatchSize ?? patchSize;
  if (!(Number.isFinite(objectPatchSize) && objectPatchSize > 0)) throw new ReferenceInputError(`reference options: objectPatchSize must be a finite length > 0 m, got ${objectPatchSize}`);

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

  // Form factors, row i = what patch i sees.
  t0 = performance.now();
  const far = { minDepth: 0, maxDepth: 2 };
  const levels = patches.map(() => [] as Vec3[][]);
  const pointsOf = (k: number, level: number): Vec3[] => (levels[k][level] ??= receiverPoints(patches[k], level));
  const F = pairFormFactors(patches, (r, e, gap) => {
    const R = patches[r];
    const E = patches[e];
    const level = R.diameter > NEAR_RECEIVER * gap ? 2 : R.diameter > MID_RECEIVER * gap ? 1 : 0;
    if (level > 0) {
      const points = pointsOf(r, level);
      let f = 0;
      for (const x of points) f += occludedFormFactor(x, R.normal, E.vertices, E.normal, occluders, far);
      return f / points.length;
    }
    if (!occluders || E.diameter > SMALL_ANGLE * gap) return occludedFormFactor(R.centroid, R.normal, E.vertices, E.normal, occluders, far);
    const f = occludedFormFactor(R.centroid, R.normal, E.vertices, E.normal, null, far);
    return f > 0 && mayOcclude(occluders, R.centroid, E.bounds) && !segmentClear(occluders, R.centroid, R.normal, E.centroid, E.normal) ? 0 : f;
  });
  const formFactorMs = performance.now() - t0;

  t0 = performance.now();
  const reflectanceOfPatch = patches.map((p) => p.reflectance);
  const { indirectRgb, exitanceRgb, sweeps, residual } = gaussSeidelRadiosity(F, reflectanceOfPatch, directRgb, tolerance, maxSweeps, 'furnished reference');
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
