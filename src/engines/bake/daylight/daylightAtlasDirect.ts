/**
 * The direct daylight of every covered atlas texel (the room's surfaces and the objects of a
 * shaped room's enclosure), as the atlas's direct map the indirect passes take
 * (`startFromDirect`'s `objects.direct`: RGB lux per atlas texel, row 0 first). Computed on the
 * CPU at each texel's G-buffer point and normal (daylightAtPoint.ts): the sky's a centre value
 * (smooth), the sun's a texel mean where the patch's edge crosses a fully covered texel
 * (sunTexelMean). Daylight is white (R = G = B).
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

/** A texel at least this covered has its sample point at its centre (rasterizeAtlas.ts), so its square around the point lies in its chart. */
const FULL_COVERAGE = 0.999;
/** Sub-samples a side where the sun patch's edge crosses a texel. */
const SUN_SUBSAMPLES = 8;

/**
 * Two unit vectors spanning the plane normal to n: horizontal and up the surface for a wall or
 * slope, x and z for a floor or ceiling — the axes of the charts of rooms drawn along x and z.
 */
function texelAxes(n: Vec3): [Vec3, Vec3] {
  const h = Math.hypot(n[0], n[2]);
  if (h < 1e-6)
    return [
      [1, 0, 0],
      [0, 0, 1],
    ];
  const t: Vec3 = [-n[2] / h, 0, n[0] / h];
  return [t, [n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0]]];
}

/**
 * The sun's mean over a fully covered texel (a square of side `size` about p): the centre value
 * where the centre and the four corners agree (the beam is uniform on a plane: only its edge
 * changes it), else the mean of SUN_SUBSAMPLES² midpoints, so the patch's flux and its edge are
 * right to a fraction of a texel (texel means, as the box walls' direct light takes them).
 */
function sunTexelMean(ctx: DaylightPointContext, p: Vec3, n: Vec3, size: number): number {
  const centre = sunDaylightAt(ctx, p, n);
  const [t, b] = texelAxes(n);
  const at = (x: number, y: number): number => sunDaylightAt(ctx, [p[0] + x * t[0] + y * b[0], p[1] + x * t[1] + y * b[1], p[2] + x * t[2] + y * b[2]], n);
  const c = 0.5 * size * (1 - 1 / SUN_SUBSAMPLES);
  if ([at(-c, -c), at(c, -c), at(-c, c), at(c, c)].every((v) => v > 0 === centre > 0)) return centre;
  let sum = 0;
  for (let j = 0; j < SUN_SUBSAMPLES; j++) for (let i = 0; i < SUN_SUBSAMPLES; i++) sum += at(((i + 0.5) / SUN_SUBSAMPLES - 0.5) * size, ((j + 0.5) / SUN_SUBSAMPLES - 0.5) * size);
  return sum / (SUN_SUBSAMPLES * SUN_SUBSAMPLES);
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
    sun[k] = position[4 * k + 3] >= FULL_COVERAGE ? sunTexelMean(ctx, p, n, prepared.atlas.texelSize) : sunDaylightAt(ctx, p, n);
    direct.fill(sky[k] + sun[k], 3 * k, 3 * k + 3);
  }
  return { direct, sky, sun, milliseconds: performance.now() - t0 };
}
