import type { LightingLuminaire, LightingScene, Vec3 } from '../core/model/lightingScene/lightingScene';
import type { Photometry } from '../core/photometry/types';
import { pointInsideRoom } from '../core/room/ceilingHeightAt';
import type { Room } from '../core/room/normaliseRoom';
import type { RoomInput } from '../core/room/roomInput';
import { roomSurfaces, type RoomSurface } from '../core/room/roomSurfaces';
import { referencePointSources, type PointSourceOptions, type ReferencePointSource } from './pointSources';
import { patchMeanRoomDirect } from './roomDirect';
import { roomPatches, type RoomPatch } from './roomPatches';
import { interreflectRoom } from './roomInterreflection';
import type { RoomSightlines } from './roomSightlines';
import { ReferenceInputError } from './referenceInputError';
import { referenceRoom } from './referenceRoom';
import { LUMINANCE_WEIGHTS } from './solveBoxReference';
import { referenceSolverOptions, type ReferenceSolverOptions } from './referenceSolverOptions';

/** Patch size (default 0.25 m), tolerance and sweeps (referenceSolverOptions.ts), and how luminaires become point sources. */
export interface RoomReferenceOptions extends PointSourceOptions, ReferenceSolverOptions {}

/** The dense form-factor matrix is N² numbers: keep it within a few hundred MB. */
export const MAX_ROOM_PATCHES = 8000;

export interface RoomReferenceResult {
  room: Room;
  surfaces: RoomSurface[];
  sight: RoomSightlines;
  sources: ReferencePointSource[];
  patches: RoomPatch[];
  /** Patch-mean illuminance per patch, lux, RGB interleaved (3 per patch). */
  directRgb: Float64Array;
  indirectRgb: Float64Array;
  /** Exitance M = ρ·(E_dir + E_ind) per patch, lm/m², RGB interleaved (0 on openings). */
  exitanceRgb: Float64Array;
  sweeps: number;
  residual: number;
  timingsMs: { direct: number; formFactors: number; solve: number };
}

/** Y (luminance-weighted) of an RGB triple at offset k. */
export function luminanceOf(rgb: ArrayLike<number>, k: number): number {
  return LUMINANCE_WEIGHTS[0] * rgb[k] + LUMINANCE_WEIGHTS[1] * rgb[k + 1] + LUMINANCE_WEIGHTS[2] * rgb[k + 2];
}

export { PieceCache, pointToPatch, visibleShare } from './roomFormFactors';

/** The luminaires as point sources, each checked to lie inside the room (and under every slope). */
function roomPointSources(room: Room, luminaires: readonly LightingLuminaire[], photometries: ReadonlyMap<string, Photometry> | Record<string, Photometry>, options: PointSourceOptions): ReferencePointSource[] {
  // The box reference's expansion (opening cells, rotation, dimming, colour) in the outline's
  // bounding box, shifted so the box starts at 0; a cell outside the room is refused below.
  const xs = room.corners.map((c) => c[0]);
  const zs = room.corners.map((c) => c[1]);
  const x0 = Math.min(...xs);
  const z0 = Math.min(...zs);
  const box: LightingScene = {
    version: 1,
    room: { width: Math.max(...xs) - x0, height: room.height, depth: Math.max(...zs) - z0, reflectance: { floor: 0, ceiling: 0, north: 0, south: 0, west: 0, east: 0 } },
    luminaires: luminaires.map((l) => ({ ...l, position: [l.position[0] - x0, l.position[1], l.position[2] - z0] as Vec3 })),
  };
  const sources = referencePointSources(box, photometries, options).map((s) => ({ ...s, position: [s.position[0] + x0, s.position[1], s.position[2] + z0] as Vec3 }));
  for (const s of sources) {
    if (!pointInsideRoom(room, s.position)) {
      const l = luminaires[s.luminaire];
      throw new ReferenceInputError(`luminaires[${s.luminaire}].position: [${l.position.join(', ')}] lies outside the room (outside the outline, or above the ceiling or a slope)`);
    }
  }
  return sources;
}

/**
 * Converged diffuse interreflection in a room of any shape (issue 29) by piecewise-constant
 * radiosity (Goral et al., SIGGRAPH 1984) on patches of every planar surface:
 *
 *   E_ind,i = Σ_j F_ij · ρ_j (E_dir,j + E_ind,j)      per RGB channel,
 *
 * F_re from the centroid — or 4 or 16 pieces — of the smaller patch r of each pair to the
 * polygon of the larger e by Lambert's contour integral times the visible share of e (sight lines
 * decided in plan, roomSightlines.ts), and F_er = F_re·A_r/A_e by reciprocity. E_dir is the
 * patch mean of point-source light shadowed by the room itself; the form factors and the sweeps
 * are roomInterreflection.ts, which daylight (solveDaylightReference.ts) shares. Openings are patches that
 * reflect nothing: the light reaching them leaves the room. Independent of src/engines/bake and
 * its shaders; the room's surfaces come from src/core/room (the contract's geometry), checked
 * here by flux balances (tests/reference/roomReference.test.ts).
 */
export function solveRoomReference(input: RoomInput, luminaires: readonly LightingLuminaire[], photometries: ReadonlyMap<string, Photometry> | Record<string, Photometry>, options: RoomReferenceOptions = {}): RoomReferenceResult {
  const room = referenceRoom(input);
  if (!Array.isArray(luminaires)) throw new ReferenceInputError('luminaires: expected an array');
  const { patchSize, tolerance, maxSweeps } = referenceSolverOptions(options);

  const sources = roomPointSources(room, luminaires, photometries, options);
  const surfaces = roomSurfaces(room);
  const sight: RoomSightlines = { convex: room.convex, corners: room.corners };
  const patches = roomPatches(surfaces, patchSize);
  const N = patches.length;
  if (N > MAX_ROOM_PATCHES) throw new ReferenceInputError(`reference options: ${N} patches exceed the limit of ${MAX_ROOM_PATCHES}; choose a larger patchSize`);

  const t0 = performance.now();
  const directRgb = new Float64Array(3 * N);
  patches.forEach((p, i) => directRgb.set(patchMeanRoomDirect(sources, sight, p), 3 * i));
  const directMs = performance.now() - t0;

  const { indirectRgb, exitanceRgb, sweeps, residual, formFactorMs, solveMs } = interreflectRoom(patches, sight, directRgb, { tolerance, maxSweeps });
  return { room, surfaces, sight, sources, patches, directRgb, indirectRgb, exitanceRgb, sweeps, residual, timingsMs: { direct: directMs, formFactors: formFactorMs, solve: solveMs } };
}

/** Where the light goes (lm, Y): Σ E·A over the room's surfaces (direct and total), Σ (1 − ρ)·E·A absorbed by them, Σ E·A through the openings. */
export function roomFluxes(r: RoomReferenceResult): { direct: number; total: number; absorbed: number; escaped: number; escapedDirect: number } {
  const out = { direct: 0, total: 0, absorbed: 0, escaped: 0, escapedDirect: 0 };
  r.patches.forEach((p, i) => {
    const d = luminanceOf(r.directRgb, 3 * i);
    const t = d + luminanceOf(r.indirectRgb, 3 * i);
    if (p.kind === 'opening') {
      out.escaped += p.area * t;
      out.escapedDirect += p.area * d;
      return;
    }
    out.direct += p.area * d;
    out.total += p.area * t;
    // (1 − ρ)·E per channel, then Y: what the surface keeps.
    const k = 3 * i;
    const kept = [0, 1, 2].map((c) => (1 - p.reflectance[c]) * (r.directRgb[k + c] + r.indirectRgb[k + c]));
    out.absorbed += p.area * luminanceOf(kept, 0);
  });
  return out;
}
