/**
 * A shop's own price list on top of the manufacturer's catalog data: the same articles and
 * rules, every `price` in another currency. This is what a shop does before passing its
 * catalog to mountLuxbox (docs/embedding.md, "Your own catalog and prices"): luxbox never
 * converts prices itself, it shows the catalog's.
 */
export interface Repricing {
  /** ISO 4217 code of the new prices. */
  currency: string;
  /** Multiplier applied to every price of the source catalog. */
  factor: number;
  /** Prices are rounded to a multiple of this (e.g. 0.05 for Swiss francs, which have no 1- or 2-rappen coins). */
  roundTo: number;
}

function roundPrice(value: number, { factor, roundTo }: Repricing): number {
  // Work in whole rounding steps, then back to two decimals, so 0.05 steps never leave binary noise (17.099999…).
  const steps = Math.round((value * factor) / roundTo);
  return Math.round(steps * roundTo * 100) / 100;
}

/**
 * A deep copy of catalog data (the JSON of docs/catalog-format.md) with `currency` replaced and
 * every value under a `price` key (a number, or an object of numbers such as the rail's
 * `{ base, perMetre }`) repriced. The result is validated by mountLuxbox like any host catalog.
 */
export function repriceCatalog(data: unknown, repricing: Repricing): unknown {
  const walk = (node: unknown, underPrice: boolean): unknown => {
    if (typeof node === 'number') return underPrice ? roundPrice(node, repricing) : node;
    if (Array.isArray(node)) return node.map((n) => walk(n, underPrice));
    if (node && typeof node === 'object') {
      return Object.fromEntries(Object.entries(node).map(([k, v]) => [k, walk(v, underPrice || k === 'price')]));
    }
    return node;
  };
  const copy = walk(data, false);
  return copy && typeof copy === 'object' ? { ...copy, currency: repricing.currency } : copy;
}
