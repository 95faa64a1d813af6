/**
 * From the daylight contract (parseDaylight.ts) to what a solver lights a room with: the sky's
 * luminance distribution, the sun as a parallel source, the ground's luminance input, and the
 * version-2 box windows as the version-3 room's openings. Pure; the baker and the reference take
 * the same conditions (docs/daylight.md).
 *
 * Illuminances not given come from the IES (1984) daylight-availability model for the sun's
 * elevation and the day (core/daylight/daylightAvailability.ts): the sky's for the sky's condition
 * (uniform and overcast: overcast; clear: clear), the sun's for a clear sky. Without a sun above
 * the horizon a sky's horizontal illuminance defaults to 10 000 lx (a daylight factor does not
 * depend on it).
 */
import { daylightAvailability } from '../../daylight/daylightAvailability';
import { CIE_CLEAR_SKY_TYPE, cieGeneralSky, cieOvercastSky, uniformSky, type Sky } from '../../daylight/skies';
import { solarPosition, sunDirection, type SolarPosition } from '../../daylight/solarPosition';
import { BOX_WALL_NAMES, type BoxWallName } from '../../room/boxRoom';
import type { RoomOpening } from '../../room/roomInput';
import type { SceneSky, SceneWindow } from './parseDaylight';

export const DEFAULT_SKY_ILLUMINANCE = 10_000;

export interface DaylightConditions {
  sky: Sky;
  /** The sun as a parallel source, when it shines (not under an overcast sky, not at night). */
  sun: { direction: [number, number, number]; normalIlluminance: number } | null;
  /** Where the sun stands (reported even under an overcast sky), when the scene gives place and time. */
  position: SolarPosition | null;
  groundReflectance: number;
  /** E_outside for daylight factors: the sky's horizontal illuminance. */
  skyHorizontalIlluminance: number;
  sunHorizontalIlluminance: number;
}

export function daylightConditions(scene: SceneSky): DaylightConditions {
  const position = scene.sun ? solarPosition(scene.sun, scene.sun) : null;
  const up = position !== null && position.elevation > 0;
  const model = up ? daylightAvailability(position.elevation, position.dayOfYear, scene.type === 'cie-clear' ? 'clear' : 'overcast') : null;
  const skyE = scene.horizontalIlluminance ?? (model ? model.skyHorizontal : DEFAULT_SKY_ILLUMINANCE);
  const direction = position ? sunDirection(position.elevation, position.azimuth) : null;
  let sky: Sky;
  if (scene.type === 'uniform') sky = uniformSky(skyE);
  else if (scene.type === 'cie-overcast') sky = cieOvercastSky(skyE);
  else sky = cieGeneralSky(CIE_CLEAR_SKY_TYPE, direction ?? [0, 1, 0], skyE);
  let sun: DaylightConditions['sun'] = null;
  if (up && direction && scene.type !== 'cie-overcast') {
    const given = scene.sun?.horizontalIlluminance;
    const normal = given !== undefined ? given / direction[1] : daylightAvailability(position.elevation, position.dayOfYear, 'clear').sunNormal;
    if (normal > 0) sun = { direction, normalIlluminance: normal };
  }
  return { sky, sun, position, groundReflectance: scene.groundReflectance, skyHorizontalIlluminance: skyE, sunHorizontalIlluminance: sun ? sun.normalIlluminance * sun.direction[1] : 0 };
}

/**
 * Version-2 windows of a box (width × depth) as the openings of its version-3 room
 * (boxRoomInput's outline: wall 0 north z = 0 from x 0 to W, 1 east x = W from z 0 to D, 2 south
 * from x W to 0, 3 west from z D to 0): the offset runs along the wall from its first corner, so
 * on the south and west walls it is measured from the other end of u. Ceiling windows (skylights)
 * have no version-3 form yet and are returned apart.
 */
export function boxWindowsAsOpenings(windows: readonly SceneWindow[], box: { width: number; depth: number }): { openings: (RoomOpening & { window: number })[]; skylights: number[] } {
  const openings: (RoomOpening & { window: number })[] = [];
  const skylights: number[] = [];
  windows.forEach((w, i) => {
    if (w.wall === 'ceiling') {
      skylights.push(i);
      return;
    }
    const wall = BOX_WALL_NAMES.indexOf(w.wall as BoxWallName);
    const length = w.wall === 'north' || w.wall === 'south' ? box.width : box.depth;
    const reversed = w.wall === 'south' || w.wall === 'west';
    openings.push({ wall, offset: reversed ? length - w.u - w.width : w.u, width: w.width, sill: w.v, height: w.height, kind: 'window', window: i });
  });
  return { openings, skylights };
}
