import defaultCatalogData from '../../core/catalog/default-catalog.json';
import { repriceCatalog } from './repriceCatalog';

/** One storefront of the demo shop: its locale, currency and the catalog priced for it. */
export interface ShopVariant {
  readonly id: 'de' | 'ch';
  readonly label: string;
  readonly locale: string;
  readonly currency: string;
  /** Catalog data as the shop would load it from its own server (docs/catalog-format.md). */
  readonly catalog: unknown;
  /** Own autosave key per storefront, so the shop never reads or overwrites the standalone app's 'luxbox.autosave.v1'. */
  readonly storageKey: string;
}

/** The room every storefront opens on (metres); 5.5 m is too short for the 6 m "Long line" preset, so the page shows a disabled action. */
export const SHOP_ROOM = { width: 5.5, depth: 4.2, height: 2.7 } as const;

/**
 * The Swiss storefront's price list: the manufacturer's EUR prices × 0.95, in CHF, rounded to
 * 5 rappen. An example of a shop supplying its own catalog; the figure is the demo's, not a rate.
 */
export const SWISS_REPRICING = { currency: 'CHF', factor: 0.95, roundTo: 0.05 } as const;

export const SHOP_VARIANTS: readonly ShopVariant[] = [
  { id: 'de', label: 'Germany · EUR', locale: 'de-DE', currency: 'EUR', catalog: defaultCatalogData, storageKey: 'lichtwerk.luxbox.de.v1' },
  { id: 'ch', label: 'Switzerland · CHF', locale: 'de-CH', currency: 'CHF', catalog: repriceCatalog(defaultCatalogData, SWISS_REPRICING), storageKey: 'lichtwerk.luxbox.ch.v1' },
];

/** The storefront named by `?shop=` (default: Germany). */
export function shopVariant(id: string | null): ShopVariant {
  return SHOP_VARIANTS.find((v) => v.id === id) ?? SHOP_VARIANTS[0];
}
