/**
 * How a module's colour temperature follows its level (docs/catalog-format.md, "Dimming curve").
 *
 * - `constant-cct`: the usual LED module, the same CCT at every level.
 * - `dim-to-warm`: the CCT falls as the module is dimmed, as a tungsten filament does. Real
 *   products state the two ends, e.g. Cree's LMH2 "Sunset Dimming" modules: 2700 K at 100 % down
 *   to 1800 K at 1 % (Cree LMH2 announcement, LEDs Magazine, 2013; also Bridgelux Vesta
 *   Dim-to-Warm 3000 K → 1800 K). Between the ends we interpolate linearly in mired (10⁶/T, a
 *   nearly perceptually uniform scale for white light, Judd 1935; CIE 15:2004 §9.3 uses it for
 *   CCT differences) against log10 of the level, which is how a filament's colour behaves over
 *   its dimming range (colour temperature roughly proportional to a power of the output):
 *
 *     u = clamp(log10(level) / log10(levelMin), 0, 1)          (0 at full, 1 at levelMin and below)
 *     mired(level) = (1 − u) · 10⁶/cctFull + u · 10⁶/cctMin
 *     cct(level) = 10⁶ / mired(level)
 *
 *   A dim-to-warm type offers exactly one nominal CCT (its `ccts` is [cctFull]); level 0 is off
 *   (no light, colour irrelevant) and gives cctMin.
 */
import { z } from 'zod/mini';

export const dimmingCurveSchema = z.discriminatedUnion('curve', [
  z.strictObject({ curve: z.literal('constant-cct') }),
  z.strictObject({
    curve: z.literal('dim-to-warm'),
    /** Kelvin at full level (the type's one offered CCT). */
    cctFull: z.number().check(z.int(), z.gte(1000), z.lte(20000)),
    /** Kelvin at `levelMin` and below; lower than cctFull. */
    cctMin: z.number().check(z.int(), z.gte(1000), z.lte(20000)),
    /** Level (0..1, exclusive) at which cctMin is reached, e.g. 0.01 for the data sheets' "1 %". */
    levelMin: z.number().check(z.gt(0), z.lt(1)),
    /** Where the two ends come from (a data sheet). */
    source: z.optional(z.string()),
  }),
]);

export type DimmingCurve = z.infer<typeof dimmingCurveSchema>;

/** The colour temperature a module shows at `level` (0..1) with nominal CCT `cct`; constant for constant-cct types and types without a curve. */
export function cctAtLevel(curve: DimmingCurve | undefined, level: number, cct: number): number {
  if (!curve || curve.curve === 'constant-cct') return cct;
  const { cctFull, cctMin, levelMin } = curve;
  const u = level <= levelMin ? 1 : level >= 1 ? 0 : Math.log10(level) / Math.log10(levelMin);
  const mired = (1 - u) * (1e6 / cctFull) + u * (1e6 / cctMin);
  return 1e6 / mired;
}
