import type { Rgb, SurfaceName, Vec3 } from '../model/lightingScene';
import type { Photometry } from '../photometry/types';

/** One luminaire with its photometry already parsed (the baker reads no files). */
export interface BakeLuminaire {
  photometry: Photometry;
  /** World position of the photometric centre, metres. */
  position: Vec3;
  /** Degrees; world = Ry(yaw) · Rx(pitch) · Ry(roll) · local (DESIGN.md). */
  yaw: number;
  pitch: number;
  roll: number;
  /** Intensity multiplier, default 1. */
  dimming?: number;
  /** Linear RGB multiplier, default [1, 1, 1]. */
  color?: Rgb;
}

/**
 * What the baker needs: the room and its luminaires. A reflectance is grey or
 * linear RGB in [0, 1). Bake a subset of luminaires (one group) to get that
 * group's basis maps: light is linear, so maps of groups add (combineMaps).
 */
export interface BakeScene {
  room: {
    width: number;
    height: number;
    depth: number;
    reflectance: Record<SurfaceName, number | Rgb>;
  };
  luminaires: BakeLuminaire[];
}

export function toRgb(value: number | Rgb): Rgb {
  return typeof value === 'number' ? [value, value, value] : [value[0], value[1], value[2]];
}
