/**
 * The direct daylight of every covered atlas texel (the room's surfaces and the objects of a
 * shaped room's enclosure), as the atlas's direct map the indirect passes take
 * (`startFromDirect`'s `objects.direct`: RGB lux per atlas texel, row 0 first). Computed on the
 * CPU at each texel's G-buffer point and normal (daylightAtPoint.ts): like the atlas's electric
 * direct light, a centre value. Daylight is white (R = G = B).
 */
import type { Vec3 } from '../../../core/model/lightingScene/lightingScene';
import type { PreparedObjects } from '../objects/preparedObjects';
import { createObjectRayCaster } from '../objects/createObjectRayCaster';
import type { BakeDaylight } from './bakeDaylight';
import { skyDaylightAt, sunDaylightAt, type DaylightPointContext } from './daylightAtPoint';
import type { BakeWindow } from './daylightWindows';

export interface DaylightAtlas {
  /** RGB lux per atlas texel, sky and sun together. */
  direct: Float32Array;
  /** The same split (Y), for the report and the tests. */
  sky: Float32Array;
  sun: Float32Array;
  milliseconds: number;
}

/**
 * `needsRays`: whether a sight line inside the room can be blocked (a room that is not convex, or
 * objects): then each sample is tested through the atlas's BVH.
 */
export function daylightPointContext(prepared: PreparedObjects, daylight: BakeDaylight, windows: readonly BakeWindow[], needsRays: boolean): DaylightPointContext {
  const caster = needsRays ? createObjectRayCaster(prepared) : null;
  return { daylight, windows, occluded: caster ? (o, d, t) => caster.anyHit(o, d, t) : null };
}

export function daylightAtlasDirect(prepared: PreparedObjects, ctx: DaylightPointContext): DaylightAtlas {
  const t0 = performance.now();
  const { width, height, position, normal } = prepared.atlas;
  const count = width * height;
  const direct = new Float32Array(3 * count);
  const sky = new Float32Array(count);
  const sun = new Float32Array(count);
  for (let k = 0; k < count; k++) {
    if (!(position[4 * k + 3] > 0)) continue;
    const p: Vec3 = [position[4 * k], position[4 * k + 1], position[4 * k + 2]];
    const n: Vec3 = [normal[4 * k], normal[4 * k + 1], normal[4 * k + 2]];
    sky[k] = skyDaylightAt(ctx, p, n);
    sun[k] = sunDaylightAt(ctx, p, n);
    direct.fill(sky[k] + sun[k], 3 * k, 3 * k + 3);
  }
  return { direct, sky, sun, milliseconds: performance.now() - t0 };
}
