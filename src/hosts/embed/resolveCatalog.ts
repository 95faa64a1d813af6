import { InputError } from '../../core/inputError';
import { parseCatalog, type Catalog } from '../../core/model/catalogSchema/catalogSchema';
import type { LuxboxOptions } from './types';

/** Bad mount options (catalog, room, currency): the message names the option. */
export class EmbedOptionsError extends InputError {
  override name = 'EmbedOptionsError';
}

/**
 * The catalog a mount uses: the host's (validated, errors name the field under
 * `options.catalog`) or the bundled one, which the caller passes (mountLuxbox.ts imports it; the
 * package's React and element doors load it only when needed, createMountController.ts). Prices
 * are never converted, so a `currency` option that differs from the catalog's is refused rather
 * than showing wrong prices.
 */
export function resolveCatalog(options: Pick<LuxboxOptions, 'catalog' | 'currency'>, bundledCatalog: Catalog | undefined): Catalog {
  if (options.catalog === undefined && bundledCatalog === undefined) throw new EmbedOptionsError('options.catalog is missing and no bundled catalog was given');
  const catalog = options.catalog === undefined ? bundledCatalog! : parseCatalog(options.catalog, 'options.catalog');
  if (options.currency !== undefined && options.currency !== catalog.currency) {
    throw new EmbedOptionsError(`options.currency is ${options.currency} but the catalog's prices are in ${catalog.currency}; pass a catalog priced in ${options.currency}`);
  }
  return catalog;
}
