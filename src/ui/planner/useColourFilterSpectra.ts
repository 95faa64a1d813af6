import { useEffect, useSyncExternalStore } from 'react';
import { colourFilterSpectraLoaded, loadColourFilterSpectra, onColourFilterSpectraLoaded } from '../../core/colour/colourFilterSpectra';

/**
 * Whether the colour-filter spectra are loaded (src/core/colour/colourFilterSpectra.ts); re-renders
 * the component when they arrive and starts loading them while `needed` (a module with a filter
 * is drawn, the filter picker is open). A failed load is retried the next time it is needed; the
 * component meanwhile draws the unfiltered colour or says it is loading.
 */
export function useColourFilterSpectra(needed: boolean): boolean {
  const ready = useSyncExternalStore(onColourFilterSpectraLoaded, colourFilterSpectraLoaded, colourFilterSpectraLoaded);
  useEffect(() => {
    if (needed && !ready) loadColourFilterSpectra().catch(() => undefined);
  }, [needed, ready]);
  return ready;
}
