// Every Vitest file starts with the colour-filter spectra loaded, as the CLI does at start and the
// browser does before any colour through a filter is computed (src/core/colour/colourFilterSpectra.ts).
// tests/core/colour/colourFilterSpectra.test.ts checks the not-yet-loaded state on a fresh module.
import { loadColourFilterSpectra } from '../../src/core/colour/colourFilterSpectra';

await loadColourFilterSpectra();
