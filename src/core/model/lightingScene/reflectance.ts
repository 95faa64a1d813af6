/**
 * Surface reflectance rules shared by validate(), the setReflectance action,
 * the scene file and the finish list.
 *
 * Why the cap is 0.95 and not "below 1": real room finishes stay below about
 * 0.9 (the best white paints measure 0.85–0.9, IES Lighting Handbook 10th ed.,
 * typical reflectances; EN 12464-1:2021 §4.2.3 recommends 0.7–0.9 for
 * ceilings), and the interreflection series Σₖ ρᵏ converges slowly near 1:
 * after n bounces the missing part of the indirect light is a fraction ρⁿ
 * (36 % after 20 bounces at ρ = 0.95, 82 % at 0.99). The baker adds that rest
 * as a geometric tail E_last·r/(1−r) (docs/baker.md, step 4), which scales the
 * noise and shape error of the last bounce by 1/(1−ρ): 20× at 0.95, 100× at
 * 0.99. The cap keeps every allowed room well inside the regime the baker is
 * validated in, with no loss for any real finish.
 */
import type { Reflectance, Rgb, SurfaceName } from './lightingScene';
import { SURFACE_NAMES } from './lightingScene';

/** Largest reflectance per channel a configuration may hold. */
export const MAX_REFLECTANCE = 0.95;

/** The four walls, in SURFACE_NAMES order. */
export const WALL_NAMES = ['north', 'south', 'west', 'east'] as const satisfies readonly SurfaceName[];

/** What a setReflectance targets: one surface, or all four walls at once. */
export type SurfaceTarget = SurfaceName | 'walls';
export const SURFACE_TARGETS = [...SURFACE_NAMES, 'walls'] as const;

/** The surfaces a target stands for. */
export function targetSurfaces(target: SurfaceTarget): readonly SurfaceName[] {
  return target === 'walls' ? WALL_NAMES : [target];
}

/** Linear RGB of a reflectance (a grey number is the same on all channels). */
export function reflectanceRgb(r: Reflectance): Rgb {
  return typeof r === 'number' ? [r, r, r] : [r[0], r[1], r[2]];
}

/**
 * Why a value cannot be a configuration's reflectance, or null when it can.
 * Checks shape (number or three numbers) and each channel finite in [0, MAX_REFLECTANCE].
 */
export function reflectanceProblem(value: unknown): string | null {
  const channels = typeof value === 'number' ? [value] : Array.isArray(value) && value.length === 3 ? (value as unknown[]) : null;
  if (!channels) return `reflectance must be a number or three numbers (linear RGB), got ${JSON.stringify(value)}`;
  for (const c of channels) {
    if (typeof c !== 'number' || !Number.isFinite(c)) return `reflectance ${JSON.stringify(value)} is not a finite number per channel`;
    if (c < 0 || c > MAX_REFLECTANCE) {
      return `reflectance ${formatReflectance(value as Reflectance)} is outside [0, ${MAX_REFLECTANCE}] (real paints stay below about 0.9, and the bounce series converges slowly near 1)`;
    }
  }
  return null;
}

/** Same light in the baker: equal per channel (grey 0.5 equals [0.5, 0.5, 0.5]). */
export function sameReflectance(a: Reflectance, b: Reflectance, tolerance = 1e-9): boolean {
  const x = reflectanceRgb(a);
  const y = reflectanceRgb(b);
  return x.every((v, i) => Math.abs(v - y[i]) <= tolerance);
}

/** Luminous reflectance: Rec. 709 / sRGB luminance weights (IEC 61966-2-1) on linear RGB. */
export function luminousReflectance(r: Reflectance): number {
  const [red, green, blue] = reflectanceRgb(r);
  return 0.2126 * red + 0.7152 * green + 0.0722 * blue;
}

/** Clamps each channel into [0, MAX_REFLECTANCE] (used only to migrate legacy scene files). */
export function capReflectance(r: Reflectance): Reflectance {
  const cap = (v: number) => Math.min(MAX_REFLECTANCE, Math.max(0, v));
  return typeof r === 'number' ? cap(r) : [cap(r[0]), cap(r[1]), cap(r[2])];
}

export function formatReflectance(r: Reflectance): string {
  const f = (v: number) => (Number.isFinite(v) ? String(Math.round(v * 1000) / 1000) : String(v));
  return typeof r === 'number' ? f(r) : `[${r.map(f).join(', ')}]`;
}
