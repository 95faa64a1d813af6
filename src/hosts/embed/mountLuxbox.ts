import { defaultCatalog } from '../../core/catalog/defaultCatalog';
import { mountConfigurator } from './mountConfigurator';
import type { LuxboxInstance, LuxboxOptions } from './types';

export { checkExpert, EmbedOptionsError, EXPERT_KEY } from './mountConfigurator';

/**
 * Mounts the configurator into `element` and returns its API (docs/embedding.md). Throws an
 * InputError subclass for bad options before touching the element.
 */
export function mountLuxbox(element: Element, options: LuxboxOptions = {}): LuxboxInstance {
  return mountConfigurator(element, options, defaultCatalog);
}
