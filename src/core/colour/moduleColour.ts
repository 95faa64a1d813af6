/**
 * The colour a module at `cct` gives through the library filter `filterId` (none: undefined):
 * the one place the model, the plan, the CLI and the filter picker turn a filter id into light.
 */
import { findColourFilter, transmissionOnCmfGrid } from './colourFilterLibrary';
import { filteredColour, type FilteredColour } from './filteredColour';

const grids = new Map<string, number[]>();

export function moduleColour(cct: number, filterId: string | undefined): FilteredColour {
  if (filterId === undefined) return filteredColour(cct, null);
  let grid = grids.get(filterId);
  if (!grid) {
    grid = transmissionOnCmfGrid(findColourFilter(filterId));
    grids.set(filterId, grid);
  }
  return filteredColour(cct, grid);
}
