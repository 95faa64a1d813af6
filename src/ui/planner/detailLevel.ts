/**
 * Map-like levels of detail (configurator paper §3.2: zooming reveals more or less detail). The level
 * follows the zoom only, so the same zoom always shows the same controls.
 *
 * - 'system': whole systems; move, rotate, rail lengths.
 * - 'module': plus buttons, distribution options, type switches, module settings.
 *
 * The threshold makes the shortest catalog module (0.15 m) at least ~40 px long on screen,
 * about the size of the 44 px touch target drawn below it, so neighbouring type switches do
 * not pile up: 0.15 m · 260 px/m = 39 px.
 */
export type DetailLevel = 'system' | 'module';

export const MODULE_LEVEL_SCALE = 260;

export function detailLevel(scale: number): DetailLevel {
  return scale >= MODULE_LEVEL_SCALE ? 'module' : 'system';
}

/**
 * Spacing of the plan's grid lines in metres: the finest of 1 m, 0.5 m, 0.1 m whose lines
 * stay at least 24 px apart, so the grid densifies as the user zooms in.
 */
export function gridStep(scale: number): number {
  for (const step of [0.1, 0.5]) if (step * scale >= 24) return step;
  return 1;
}
