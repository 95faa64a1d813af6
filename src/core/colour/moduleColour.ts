/**
 * The colour a module at `cct` gives through the library filter `filterId` (none: undefined):
 * the one place the model, the plan, the CLI and the filter picker turn a filter id into light.
 * With a filter it needs the loaded spectra (./colourFilterSpectra.ts): before that it throws
 * ColourFilterSpectraPending; `needsColourFilterSpectra` tells a host when to load them first.
 */
import { colourFilterSpectraLoaded, filterSpectrum, transmissionOnCmfGrid } from './colourFilterSpectra';
import { filteredColour, type FilteredColour } from './filteredColour';

const grids = new Map<string, number[]>();

export function moduleColour(cct: number, filterId: string | undefined): FilteredColour {
  if (filterId === undefined) return filteredColour(cct, null);
  let grid = grids.get(filterId);
  if (!grid) {
    grid = transmissionOnCmfGrid(filterSpectrum(filterId));
    grids.set(filterId, grid);
  }
  return filteredColour(cct, grid);
}

/** Whether computing the colour of these filters (ids, undefined = none) must wait for the spectra. */
export function needsColourFilterSpectra(filterIds: Iterable<string | undefined>): boolean {
  if (colourFilterSpectraLoaded()) return false;
  for (const id of filterIds) if (id !== undefined) return true;
  return false;
}
