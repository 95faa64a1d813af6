/**
 * Daylight in a room of any shape (issue 30), independent of the baker: the sky, the ground
 * and the sun through the room's windows (daylightDirect.ts) as patch-mean direct illuminance,
 * then the diffuse interreflection the luminaires' reference uses (roomInterreflection.ts).
 * Daylight is white here (the same value on R, G and B), so the room's RGB finishes still tint
 * what it reflects. Checked by tests/reference/daylightReference.test.ts: exact form factors for a
 * uniform sky, an independent integration for the CIE overcast sky, the sun patch's geometry,
 * and the flux balance (entering = absorbed + leaving).
 */
import type { Glazing } from '../core/daylight/glazing';
import { OPEN_OPENING } from '../core/daylight/glazing';
import { groundLuminance, type Sky } from '../core/daylight/skies';
import type { Rgb, Vec3 } from '../core/model/lightingScene/lightingScene';

import type { RoomInput } from '../core/room/roomInput';
import { roomSurfaces } from '../core/room/roomSurfaces';
import { daylightDirectAt, daylightWindows, patchMeanDaylight, transmittedSkyOnWindow, transmittedSunOnWindow, type DaylightContext, type ReferenceSun } from './daylightDirect';
import { ReferenceInputError } from './referenceInputError';
import { referenceRoom } from './referenceRoom';
import { roomIlluminanceAt, type RoomSample } from './roomIlluminanceAt';
import { interreflectRoom } from './roomInterreflection';
import { roomPatches } from './roomPatches';
import type { RoomSightlines } from './roomSightlines';
import { MAX_ROOM_PATCHES, type RoomReferenceResult } from './solveRoomReference';

export interface DaylightReferenceInput {
  /** The sky (core/daylight/skies), or null for the sun alone. */
  sky: Sky | null;
  sun: ReferenceSun | null;
  /** Reflectance of the ground outside, 0 … < 1 (issue 30's default 0.2). */
  groundReflectance: number;
  /** Glazing per window, by the opening's index in the room input; a window not listed is an open hole. */
  glazing?: Readonly<Record<number, Glazing>>;
}

export interface DaylightReferenceOptions {
  /** Edge of the patch lattice, metres (default 0.25). */
  patchSize?: number;
  tolerance?: number;
  maxSweeps?: number;
}

export interface DaylightReferenceResult extends RoomReferenceResult {
  daylight: DaylightContext;
  /** Direct daylight per patch split into sky (with ground) and sun, lux (Y). */
  skyDirect: Float64Array;
  sunDirect: Float64Array;
  /** Light entering through all windows, lm, from the windows' outer faces (independent of the patches). */
  entering: { sky: number; sun: number; total: number };
}

/** Solve the room's daylight; throws ReferenceInputError for a bad room or option. */
export function solveDaylightReference(input: RoomInput, daylight: DaylightReferenceInput, options: DaylightReferenceOptions = {}): DaylightReferenceResult {
  const room = referenceRoom(input);
  const patchSize = options.patchSize ?? 0.25;
  if (!(Number.isFinite(patchSize) && patchSize > 0)) throw new ReferenceInputError(`reference options: patchSize must be a finite length > 0 m, got ${patchSize}`);
  const tolerance = options.tolerance ?? 1e-6;
  const maxSweeps = options.maxSweeps ?? 10_000;
  if (!(daylight.groundReflectance >= 0 && daylight.groundReflectance < 1)) throw new ReferenceInputError(`daylight: groundReflectance must be in [0, 1), got ${daylight.groundReflectance}`);
  const sun = daylight.sun;
  if (sun && !(Math.abs(Math.hypot(...sun.direction) - 1) < 1e-9 && sun.normalIlluminance >= 0)) throw new ReferenceInputError('daylight: the sun needs a unit direction and an illuminance ≥ 0');

  const surfaces = roomSurfaces(room);
  const sight: RoomSightlines = { convex: room.convex, corners: room.corners };
  const glazing = daylight.glazing ?? {};
  const sunHorizontal = sun && sun.direction[1] > 0 ? sun.normalIlluminance * sun.direction[1] : 0;
  const ctx: DaylightContext = {
    windows: daylightWindows(surfaces, (i) => glazing[i] ?? OPEN_OPENING),
    sight,
    sky: daylight.sky,
    sun,
    groundLuminance: groundLuminance(daylight.sky?.horizontalIlluminance ?? 0, sunHorizontal, daylight.groundReflectance),
  };
  const patches = roomPatches(surfaces, patchSize);
  const N = patches.length;
  if (N > MAX_ROOM_PATCHES) throw new ReferenceInputError(`reference options: ${N} patches exceed the limit of ${MAX_ROOM_PATCHES}; choose a larger patchSize`);

  const t0 = performance.now();
  const directRgb = new Float64Array(3 * N);
  const skyDirect = new Float64Array(N);
  const sunDirect = new Float64Array(N);
  patches.forEach((p, i) => {
    const e = patchMeanDaylight(ctx, p);
    skyDirect[i] = e.sky;
    sunDirect[i] = e.sun;
    directRgb.fill(e.sky + e.sun, 3 * i, 3 * i + 3);
  });
  const directMs = performance.now() - t0;
  const { indirectRgb, exitanceRgb, sweeps, residual, formFactorMs, solveMs } = interreflectRoom(patches, sight, directRgb, { tolerance, maxSweeps });

  let skyIn = 0;
  let sunIn = 0;
  for (const w of ctx.windows) {
    skyIn += w.area * transmittedSkyOnWindow(ctx, w);
    sunIn += w.area * transmittedSunOnWindow(ctx, w);
  }
  return {
    room,
    surfaces,
    sight,
    sources: [],
    patches,
    directRgb,
    indirectRgb,
    exitanceRgb,
    sweeps,
    residual,
    timingsMs: { direct: directMs, formFactors: formFactorMs, solve: solveMs },
    daylight: ctx,
    skyDirect,
    sunDirect,
    entering: { sky: skyIn, sun: sunIn, total: skyIn + sunIn },
  };
}

/** Daylight illuminance (lux) at p with normal n in a solved room: exact direct daylight plus the final gather of the patches' exitance. */
export function daylightIlluminanceAt(r: DaylightReferenceResult, p: Vec3, n: Vec3): RoomSample {
  return roomIlluminanceAt(r, p, n, (q: Vec3, m: Vec3, out: Rgb) => out.fill(daylightDirectAt(r.daylight, q, m)) as Rgb);
}
