import { colourFilterSpectraLoaded, loadColourFilterSpectra } from '../../core/colour/colourFilterSpectra';
import { configurationFilterIds } from '../../core/model/modules/moduleFilter';
import type { ConfiguratorStore } from '../../core/store/createConfiguratorStore';

/**
 * Loads the colour-filter spectra as soon as the configuration (its modules or its light scenes)
 * uses a filter: at mount for a restored or shared configuration, on the change that adds the
 * first filter otherwise (docs/colour-filters.md, "Two files"). A configuration without filters
 * never fetches them. Returns `ready()`, which resolves when what the current configuration needs
 * is loaded, and the unsubscribe function.
 */
export function keepColourFilterSpectra(store: ConfiguratorStore): { ready: () => Promise<void>; stop: () => void } {
  const uses = () => configurationFilterIds(store.getState().config).length > 0;
  const ensure = () => (uses() && !colourFilterSpectraLoaded() ? loadColourFilterSpectra().then(() => undefined) : Promise.resolve());
  // A failed fetch is retried on the next change that needs it, or by ready().
  const load = () => void ensure().catch((error: unknown) => console.error('luxbox: could not load the colour-filter spectra', error));
  load();
  const stop = store.subscribe((s, prev) => {
    if (s.config !== prev.config) load();
  });
  return { ready: ensure, stop };
}
