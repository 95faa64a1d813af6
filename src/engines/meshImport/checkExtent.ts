import { InputError } from '../../core/inputError';
import type { Bounds3 } from '../../core/mesh/triangleMesh';
import { PLAUSIBLE_EXTENT_M } from './meshUnits';

/**
 * Farthest a vertex of an imported model may lie from its origin, metres, after the unit is
 * applied: no room luxbox plans is near 100 m across (the widest shop floor in the presets is 7 m),
 * so anything beyond is a wrong unit or a broken file, never furniture (issue 32: a vertex at
 * 3.4e38 m was accepted when the unit was chosen by hand).
 */
export const MAX_IMPORT_COORDINATE_M = 100;

/**
 * The bounds of the model in metres, checked whatever the unit choice: a coordinate beyond
 * MAX_IMPORT_COORDINATE_M (or not finite) refuses it, a largest extent outside the plausible
 * range (0.05–30 m) warns. `warnedSize`: a caller already warned about the size.
 */
export function checkExtent(name: string, bounds: Bounds3, unit: string, warnings: string[], warnedSize: boolean): void {
  const reach = Math.max(...bounds.min.map(Math.abs), ...bounds.max.map(Math.abs));
  if (!(reach <= MAX_IMPORT_COORDINATE_M)) {
    throw new InputError(`${name}: a vertex lies ${round(reach)} m from the model's origin in ${unit}; at most ${MAX_IMPORT_COORDINATE_M} m (no room is larger) — check the units or the file`);
  }
  const extent = Math.max(...bounds.max.map((hi, a) => hi - bounds.min[a]));
  if (!warnedSize && (extent < PLAUSIBLE_EXTENT_M.min || extent > PLAUSIBLE_EXTENT_M.max)) {
    warnings.push(`${name}: ${round(extent)} m across in ${unit} — check the units`);
  }
}

function round(x: number): number {
  return Number(x.toPrecision(4));
}
