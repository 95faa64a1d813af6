/**
 * Daylight as the baker takes it (issue 30, docs/daylight.md "The baker"): the sky's luminance
 * distribution, the ground seen below the horizon, the sun as a parallel source, and the glazing
 * of each window by its opening's index in the room's input. Only rooms with a shape
 * (`BakeScene.room.shape`) have windows; a version-2 box with `windows` becomes such a room
 * (core/model/lightingScene/daylightConditions.ts, boxWindowsAsOpenings).
 */
import type { Glazing } from '../../../core/daylight/glazing';
import type { Sky } from '../../../core/daylight/skies';

export interface BakeSun {
  /** Unit vector toward the sun (x east, y up, z south). */
  direction: readonly [number, number, number];
  /** Illuminance on a plane normal to the beam, lux. */
  normalIlluminance: number;
}

export interface BakeDaylight {
  /** The sky, or null for the sun alone. */
  sky: Sky | null;
  sun: BakeSun | null;
  /** cd/m² of the ground outside, seen through a window below the horizon (core/daylight/skies.ts groundLuminance). */
  groundLuminance: number;
  /** Glazing by the opening's input index; a window not listed is an open hole (τ = 1). */
  glazing: ReadonlyMap<number, Glazing>;
  /** The ground's reflectance ρ_g behind groundLuminance (absent: recovered from it, workPlaneDaylightFactor.ts groundReflectanceOf); the daylight factor's ground. */
  groundReflectance?: number;
}
