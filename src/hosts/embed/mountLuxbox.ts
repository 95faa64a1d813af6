import { mountConfigurator } from './mountConfigurator';
// After mountConfigurator on purpose: the first-screen chunk places modules in import order, and the catalog's JSON
// placed before the configurator's code compresses 0.3 kB worse (docs/benchmarks.md, "The package's React door").
import { defaultCatalog } from '../../core/catalog/defaultCatalog';
import type { LuxboxInstance, LuxboxOptions } from './types';

export { checkExpert, EmbedOptionsError, EXPERT_KEY } from './mountConfigurator';

/**
 * Mounts the configurator into `element` and returns its API (docs/embedding.md). Throws an
 * InputError subclass for bad options before touching the element.
 */
export function mountLuxbox(element: Element, options: LuxboxOptions = {}): LuxboxInstance {
  return mountConfigurator(element, options, defaultCatalog);
}
