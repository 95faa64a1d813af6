/** Outdoor horizontal illuminance of the overcast sky a daylight factor is computed under, lux (a DF does not depend on it; the report and the 3D view bake at this one). */
export const DAYLIGHT_FACTOR_SKY_ILLUMINANCE = 10_000;

/**
 * The daylight factor and its statistics. DF = 100 % × E_inside / E_outside, with E_outside the
 * horizontal illuminance on an unobstructed plane under the same (CIE standard overcast) sky
 * (CIE 17.4 / ILV 17-21-012; BS 8206-2; EN 17037:2018, which states its targets as daylight
 * factors on the reference plane). EN 17037's minimum level for daylight provision through
 * vertical and inclined openings: D ≥ D_T (the factor that gives 300 lx, about 2 % for the
 * median outdoor diffuse illuminance of central Europe) over 50 % of the reference plane, and
 * D ≥ D_TM (100 lx, about 0.7 %) over 95 % of it (EN 17037:2018, table A.1; D = 100 × E_target /
 * E_v,d,med, table A.3 lists E_v,d,med per capital).
 */

export function daylightFactor(insideIlluminance: number, outsideHorizontalIlluminance: number): number {
  return (100 * insideIlluminance) / outsideHorizontalIlluminance;
}

/** EN 17037's daylight factor for a target illuminance (lux) where the median outdoor diffuse illuminance is E_v,d,med (lux). */
export function targetDaylightFactor(targetIlluminance: number, medianOutdoorDiffuse: number): number {
  return (100 * targetIlluminance) / medianOutdoorDiffuse;
}

export interface DaylightFactorTargets {
  /** D_T, %: default 2 (300 lx). */
  target: number;
  /** Share of the plane that must reach D_T: default 0.5. */
  targetShare: number;
  /** D_TM, %: default 0.7 (100 lx). */
  minimumTarget: number;
  /** Share of the plane that must reach D_TM: default 0.95. */
  minimumTargetShare: number;
}

export const EN17037_MINIMUM: DaylightFactorTargets = { target: 2, targetShare: 0.5, minimumTarget: 0.7, minimumTargetShare: 0.95 };

export interface DaylightFactorStatistics {
  /** Area-weighted mean DF, %. */
  average: number;
  minimum: number;
  maximum: number;
  /** Minimum / average (0 where the average is 0). */
  uniformity: number;
  /** Area share (0 … 1) with DF ≥ target. */
  shareAtTarget: number;
  /** Area share with DF ≥ minimumTarget. */
  shareAtMinimumTarget: number;
  /** Both shares reached. */
  meetsTargets: boolean;
  /** The median DF (area-weighted; the lower of the two values that straddle half the area). */
  median: number;
}

/**
 * Statistics of daylight factors (%) at points of a plane, each standing for an area (weights;
 * equal when absent): a work plane's grid or a floor's texels.
 */
export function daylightFactorStatistics(values: ArrayLike<number>, weights?: ArrayLike<number>, targets: DaylightFactorTargets = EN17037_MINIMUM): DaylightFactorStatistics {
  const n = values.length;
  if (n === 0) throw new RangeError('daylight factor statistics need at least one value');
  if (weights && weights.length !== n) throw new RangeError(`${n} values but ${weights.length} weights`);
  let total = 0;
  let sum = 0;
  let atTarget = 0;
  let atMinimum = 0;
  let minimum = Infinity;
  let maximum = -Infinity;
  const order: number[] = [];
  for (let i = 0; i < n; i++) {
    const v = values[i];
    const w = weights ? weights[i] : 1;
    if (!Number.isFinite(v) || !(w >= 0) || !Number.isFinite(w)) throw new RangeError(`value ${i} (${v}) or its weight (${w}) is not a finite number ≥ 0`);
    total += w;
    sum += w * v;
    if (v >= targets.target) atTarget += w;
    if (v >= targets.minimumTarget) atMinimum += w;
    minimum = Math.min(minimum, v);
    maximum = Math.max(maximum, v);
    order.push(i);
  }
  if (!(total > 0)) throw new RangeError('daylight factor statistics need a positive total weight');
  order.sort((a, b) => values[a] - values[b]);
  let running = 0;
  let median = values[order[n - 1]];
  for (const i of order) {
    running += weights ? weights[i] : 1;
    if (running >= total / 2) {
      median = values[i];
      break;
    }
  }
  const average = sum / total;
  const shareAtTarget = atTarget / total;
  const shareAtMinimumTarget = atMinimum / total;
  return {
    average,
    minimum,
    maximum,
    uniformity: average > 0 ? minimum / average : 0,
    shareAtTarget,
    shareAtMinimumTarget,
    meetsTargets: shareAtTarget >= targets.targetShare && shareAtMinimumTarget >= targets.minimumTargetShare,
    median,
  };
}

/**
 * The daylight-factor map's legend levels, %: EN 17037's D_TM (about 0.7 %) and D_T (2 %) fall
 * between and on them, and 5 % is where BS 8206-2 calls a room well daylit. The one definition the
 * 3D view's DF mode and its legend read.
 */
export const DAYLIGHT_FACTOR_LEVELS: readonly number[] = [0.5, 1, 2, 3, 5, 10];

/** The DF levels as illuminance under the overcast sky of DAYLIGHT_FACTOR_SKY_ILLUMINANCE (lux): what the false-colour shader compares the maps with. */
export function daylightFactorLuxLevels(levels: readonly number[] = DAYLIGHT_FACTOR_LEVELS): number[] {
  return levels.map((df) => (df * DAYLIGHT_FACTOR_SKY_ILLUMINANCE) / 100);
}
