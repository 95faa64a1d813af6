/**
 * Display colours for surface finishes: the finish's own sRGB swatch when the
 * surface holds a listed finish, otherwise the sRGB encoding of its linear
 * reflectance (what that albedo looks like under white light), and the light
 * tint the plan paints its floor with.
 */
import type { Reflectance } from '../../core/model/lightingScene/lightingScene';
import { reflectanceRgb } from '../../core/model/lightingScene/reflectance';
import { matchFinish, type SurfaceFinish } from '../../core/model/catalogSchema/surfaceFinish';

/** sRGB transfer function (IEC 61966-2-1:1999), linear 0..1 → byte. */
function encodeSrgb(linear: number): number {
  const c = Math.min(1, Math.max(0, linear));
  const v = c <= 0.0031308 ? 12.92 * c : 1.055 * c ** (1 / 2.4) - 0.055;
  return Math.round(v * 255);
}

const hex = (bytes: readonly number[]) => `#${bytes.map((b) => b.toString(16).padStart(2, '0')).join('')}`;

/** '#rrggbb' showing a linear-RGB reflectance under white light (sRGB encoded). */
export function rgbColour(linear: readonly [number, number, number]): string {
  return hex(linear.map(encodeSrgb));
}

/** '#rrggbb' for a surface's reflectance. */
export function finishColour(value: Reflectance, finishes: readonly SurfaceFinish[]): string {
  const f = matchFinish(finishes, value);
  return f ? f.display.toLowerCase() : hex(reflectanceRgb(value).map(encodeSrgb));
}

/**
 * The plan's floor fill: the floor colour mixed with white (in sRGB bytes, `amount` of the
 * colour), light enough that grid lines, rails and light footprints stay readable on a dark floor.
 */
export function floorTint(value: Reflectance, finishes: readonly SurfaceFinish[], amount = 0.15): string {
  const c = finishColour(value, finishes);
  const bytes = [1, 3, 5].map((i) => parseInt(c.slice(i, i + 2), 16));
  return hex(bytes.map((b) => Math.round(255 + (b - 255) * amount)));
}
