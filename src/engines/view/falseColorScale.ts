import type { Rgb } from '../../core/model/lightingScene/lightingScene';

/** At most this many legend levels (the shader's uniform array size). */
export const MAX_LEVELS = 10;

/**
 * Legend levels for a false-colour lux view: a 1–2–5 series per decade (the
 * steps lighting plans use, e.g. 100, 200, 500 lx) from about 1/100 of the top
 * value up to the first step at or above it, thinned to at most MAX_LEVELS.
 */
export function luxLevels(maxLux: number): number[] {
  const top = Number.isFinite(maxLux) && maxLux > 0 ? maxLux : 1;
  const series: number[] = [];
  for (let e = Math.floor(Math.log10(top / 100)) - 1; series.length === 0 || series[series.length - 1] < top; e++) {
    for (const m of [1, 2, 5]) series.push(m * 10 ** e);
  }
  let levels = series.filter((v) => v >= top / 120);
  const last = levels.findIndex((v) => v >= top);
  levels = levels.slice(0, last + 1);
  while (levels.length > MAX_LEVELS) levels = levels.filter((_, i) => i % 2 === (levels.length - 1) % 2);
  return levels.map((v) => Number(v.toPrecision(3)));
}

/**
 * Turbo colour map (Anton Mikhailov, Google AI Blog 2019, Apache-2.0), polynomial
 * approximation by Ruofei Du: perceptually ordered, readable from blue (low) to
 * red (high). t in 0..1 → sRGB 0..1. The shader uses the same polynomial.
 */
export function turbo(t: number): Rgb {
  const x = Math.min(1, Math.max(0, t));
  const x2 = x * x;
  const x3 = x2 * x;
  const x4 = x2 * x2;
  const x5 = x4 * x;
  const c = (k: number[]) => Math.min(1, Math.max(0, k[0] + k[1] * x + k[2] * x2 + k[3] * x3 + k[4] * x4 + k[5] * x5));
  return [c(TURBO_R), c(TURBO_G), c(TURBO_B)];
}

export const TURBO_R = [0.13572138, 4.6153926, -42.66032258, 132.13108234, -152.94239396, 59.28637943];
export const TURBO_G = [0.09140261, 2.19418839, 4.84296658, -14.18503333, 4.27729857, 2.82956604];
export const TURBO_B = [0.1066733, 12.64194608, -60.58204836, 110.36276771, -89.90310912, 27.34824973];

/** Position 0..1 of a lux value on the legend: piecewise linear in log(lux) between levels (as in the shader). */
export function legendPosition(lux: number, levels: readonly number[]): number {
  if (levels.length < 2) return 0;
  const l = Math.log(Math.max(lux, 1e-6));
  for (let i = 0; i < levels.length - 1; i++) {
    const a = Math.log(levels[i]);
    const b = Math.log(levels[i + 1]);
    if (l < b || i === levels.length - 2) return Math.min(1, Math.max(0, (i + (l - a) / (b - a)) / (levels.length - 1)));
  }
  return 1;
}

/**
 * The levels as the shader takes them (uLevels, uLevelCount): the first
 * MAX_LEVELS positive ones, the rest of the array 1 (log 1 = 0, never read
 * past the count but kept finite).
 */
export function shaderLevels(levels: readonly number[]): { count: number; values: number[] } {
  const ls = levels.slice(0, MAX_LEVELS).filter((v) => v > 0);
  return { count: ls.length, values: Array.from({ length: MAX_LEVELS }, (_, i) => ls[i] ?? 1) };
}
