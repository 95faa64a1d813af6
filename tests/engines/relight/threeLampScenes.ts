import type { Rgb } from '../../../src/core/model/lightingScene/lightingScene';
import type { BakeScene } from '../../../src/engines/bake/bakeScene';
import { spot } from '../bake/bakeTestKit';

/** The small, quick bake the relight tests compare their paths on; each test file keeps its own seed. */
export const relightTestSettings = (seed: number) => ({ texelSize: 0.2, maxTextureSize: 32, samples: 16, bounces: 2, samplesPerDraw: 8, blurRadius: 1, seed });

/** A 4 × 2.6 × 3 m room with one coloured wall, so colour and dimming both show in the maps. */
export const relightTestRoom: BakeScene['room'] = { width: 4, height: 2.6, depth: 3, reflectance: { floor: 0.3, ceiling: 0.8, north: [0.7, 0.5, 0.3], south: 0.6, west: 0.5, east: 0.4 } };

/** Where the three spots hang and how bright and tilted each is (lamp k: base + k × step). */
export interface ThreeLamps {
  flux: [base: number, step: number];
  beamDegrees: number;
  pitchStep: number;
  x: [base: number, step: number];
  z: [base: number, step: number];
}

/**
 * Three spots with per-lamp dimming and colour (a light scene's look as toLightingScene hands it
 * over): `looks[k]` is lamp k's [dimming, colour].
 */
export function threeLampScenes(lamps: ThreeLamps): (looks: [number, Rgb][]) => BakeScene {
  const photometries = Array.from({ length: 3 }, (_, k) => spot(lamps.flux[0] + lamps.flux[1] * k, lamps.beamDegrees, 15, 2));
  return (looks) => ({
    room: relightTestRoom,
    luminaires: looks.map(([dimming, color], k) => ({
      photometry: photometries[k],
      position: [lamps.x[0] + lamps.x[1] * k, 2.3, lamps.z[0] + lamps.z[1] * k] as [number, number, number],
      yaw: 0,
      pitch: lamps.pitchStep * k,
      roll: 0,
      dimming,
      color,
    })),
  });
}

/**
 * The two light scenes the relight tests fade between: in A lamp 0 warm at full, lamp 1 white at
 * 30 %, lamp 2 off; in B lamp 0 warm at 20 %, lamp 1 cool at full, lamp 2 warmer at `lastDimming`.
 */
export function fadeScenes(scene: (looks: [number, Rgb][]) => BakeScene, lastDimming = 0.8): { A: BakeScene; B: BakeScene } {
  const A = scene([
    [1, [1, 0.8, 0.6]],
    [0.3, [1, 1, 1]],
    [0, [1, 1, 1]],
  ]);
  const B = scene([
    [0.2, [1, 0.8, 0.6]],
    [1, [0.9, 0.95, 1]],
    [lastDimming, [1, 0.7, 0.4]],
  ]);
  return { A, B };
}
